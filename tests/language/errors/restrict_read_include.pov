// A scene may not include files outside its folders (File_Restrictions).
#version 3.7;
#include "/etc/passwd"
