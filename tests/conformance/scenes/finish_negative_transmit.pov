// Negative filter and transmit (issue 22, transmitfx.pov): the opaque rest
// 1 - filter - transmit grows above 1 and what lies behind is subtracted
// (measured: rgb 0.5 transmit -1 over a background B shows 1 - B), so
// the ray goes on whenever filter or transmit is not zero.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 10, -8> rgb 1 }
plane { y, 0 pigment { checker rgb <0.1, 0.4, 0.9> rgb <0.9, 0.6, 0.1> scale 0.5 } }
#macro Pane(X, C, F, T)
    // One surface (a disc): a box's two faces would cancel each other.
    disc { <X, 0.9, -1>, z, 0.65 pigment { rgb C filter F transmit T }
           finish { ambient 1 diffuse 0 } no_shadow }
#end
Pane(-2.2, <0.5, 0.5, 0.3>, 0, -1)
Pane(-0.75, <0.5, 0.5, 0.3>, 0, -0.4)
Pane(0.75, <0.6, 0.4, 0.3>, -0.8, 0)
Pane(2.2, <0.4, 0.5, 0.6>, -0.3, -0.3)
