// A text object whose font file does not exist.
#version 3.7;
text { ttf "no_such_font.ttf" "Hi" 1, 0 }
