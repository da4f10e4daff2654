// A scene may not write outside its folders (File_Restrictions).
#version 3.7;
#fopen Out "/tmp/frameray_restrict_test.txt" write
#write (Out, "owned")
#fclose Out
