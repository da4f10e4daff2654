// A scene may not escape its folder with ../ (File_Restrictions).
#version 3.7;
#fopen Out "../frameray_restrict_test.txt" write
#fclose Out
