// Error test: julia_fractal's hypercomplex cube is not reproduced (the
// cube of povray's hypercomplex numbers gives another shape, measured), so
// frameray stops on it rather than rendering something else.
#version 3.7;
julia_fractal { <0.3, -0.2, 0.4, 0> hypercomplex cube max_iteration 6 }
