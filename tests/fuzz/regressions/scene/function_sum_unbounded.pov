#declare F = function { prod(i, 0, 0/0, i) + sum(j, 1e300, 1e300, j) };
#declare X = F(0, 0, 0);
