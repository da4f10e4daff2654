// A misspelled object keyword: the error suggests the keyword meant.
#version 3.7;
spher { 0, 1 }
