#declare F = function { sum(i, 0, 1e12, i) };
#declare X = F(0, 0, 0);
