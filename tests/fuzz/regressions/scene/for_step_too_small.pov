#for (I, 0, 1e300, 1e-300)
#end
