// A normal's optional bump size in every form povray reads there: any
// numeric expression (the clock, a signed number, a float function, a
// float identifier, a vector's component, a user function call), and after
// a comma following the pattern's own arguments (`gradient x, 5.6`).
// Rendered with +K0.4, so `bumps clock` has a bump size of 0.4.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 52 }
light_source { <-6, 8, -10> color rgb 1 }
#declare Size = 0.9;
#declare Sizes = <0.3, 1.2, 0.5>;
#declare Twice = function(a) { 2 * a };
#macro Ball(Pos, Normal)
  sphere { Pos, 0.9
    pigment { color rgb <0.9, 0.8, 0.6> }
    finish { phong 0.4 }
    normal { Normal scale 0.25 }
  }
#end
Ball(<-3, 2, 0>, normal { bumps clock })
Ball(<-1, 2, 0>, normal { bumps +0.5 })
Ball(< 1, 2, 0>, normal { bumps sin(1.2) })
Ball(< 3, 2, 0>, normal { dents Size })
Ball(<-3, 0, 0>, normal { wrinkles Sizes.y })
Ball(<-1, 0, 0>, normal { bumps Twice(0.4) })
Ball(< 1, 0, 0>, normal { gradient x, 5.6 })
Ball(< 3, 0, 0>, normal { ripples, 0.8 })
Ball(<-3, -2, 0>, normal { bumps pi / 4 })
Ball(<-1, -2, 0>, normal { bumps (clock + 0.2) })
Ball(< 1, -2, 0>, normal { checker, 0.6 })
Ball(< 3, -2, 0>, normal { bumps true })
