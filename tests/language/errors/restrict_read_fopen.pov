// A scene may not read files outside its folders (File_Restrictions).
#version 3.7;
#fopen In "/etc/passwd" read
