// An error inside a macro called from a macro: the chain is shown.
#version 3.7;
#macro Inner(X)
  (X + Missing)
#end
#macro Outer(Y)
  Inner(Y)
#end
#declare A = Outer(1);
