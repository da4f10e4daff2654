// A call of a macro whose name is misspelled.
#version 3.7;
#macro MakeBall(R) sphere { 0, R } #end
object { MakeBal(1) }
