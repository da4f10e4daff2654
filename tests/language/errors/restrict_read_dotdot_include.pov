// ../ escapes are resolved before the check (File_Restrictions).
#version 3.7;
#include "../../../../../../../../../../../../etc/passwd"
