// Language test: declarations whose value ends with '}'. A #local whose
// value a macro produced is bound in the scope where the #local stands
// (the macro's own scope may still be open when the '}' ends the value),
// and a declared texture takes the texture blocks that follow it as layers
// without running the next line's directive first.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#fopen Out "declared_blocks.out" write

#macro Shift() transform { translate <1, 2, 3> } #end
#macro Use()
  #local M = Shift()
  #local S = sphere { 0, 1 transform M }
  min_extent(S)
#end
#declare V = Use();
#write (Out, "transform from a macro: ", V, "\n")

#declare Layered = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
#declare Copy = texture { Layered }
#declare Ball = sphere { 0, 1 texture { Copy } translate x }
#write (Out, "layered texture declared: ", max_extent(Ball), "\n")
#fclose Out
