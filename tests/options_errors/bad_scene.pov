// A scene with a mistake: its error must reach the console even when
// every text stream is switched off (-GA).
#version 3.7;
sphere { 0, 1 pigment { rgb 1 } frobnicate }
