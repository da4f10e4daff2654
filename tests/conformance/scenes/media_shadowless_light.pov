// A shadowless light adds nothing to scattering media (measured with
// povray 3.7; advanced/benchmark's clouds are lit by the sun and a
// shadowless fill light). A box of scattering media over a floor, lit by
// a point light and a brighter shadowless light from the other side: only
// the point light scatters in the box; the shadowless one still lights
// the floor.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 6, -2> rgb 1 }
light_source { <5, 3, -3> rgb 2 shadowless }
plane { y, 0 pigment { checker rgb 0.3 rgb 0.7 } }
box { <-1.5, 0.2, -1>, <1.5, 2, 1>
  pigment { rgbt 1 } hollow
  interior { media { scattering { 1, 0.4 } absorption 0.1 samples 10, 10 } }
}
