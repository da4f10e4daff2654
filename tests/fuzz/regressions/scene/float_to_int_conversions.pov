#declare X = str(1, 1e300, -1e300);
#declare Y = vstr(1e300, 1, "", 1e300, 1e300);
#declare Z = chr(1e300) + substr("abc", 1e300, 1e300);
#declare R = rand(seed(-1e300)) + bitwise_and(1e300, -1e300);
