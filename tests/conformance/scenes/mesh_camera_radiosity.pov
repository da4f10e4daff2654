// Conformance: a mesh_camera under radiosity. The pretrace and the final
// pass trace the mesh camera's own rays (one per face, distribution 0),
// so the indirect light of the room is there as with any other camera.
// The grid is an orthographic view tilted down into a closed room lit by
// one light.
#version 3.7;
global_settings { assumed_gamma 1
  radiosity { count 300 recursion_limit 1 nearest_count 10 error_bound 0.4
              pretrace_start 0.08 pretrace_end 0.02 } }
#declare W = 80; #declare H = 60;
#declare S = 3 / W;  // face size
#declare Grid = mesh {
  #for (J, 0, H - 1)
    #for (I, 0, W - 1)
      #local X = -1.5 + I * S; #local Y = 1.125 - (J + 2) * S;
      triangle { <X, Y, 0>, <X + S, Y + S, 0>, <X + S, Y, 0> }
    #end
  #end
}
camera {
  mesh_camera { 1 0 mesh { Grid rotate x * 15 translate <0, 1.3, -1.8> } }
  location <0, 0, -0.01>
}
light_source { <0.5, 2.6, -0.5> rgb 1 }
#declare F = finish { ambient 0 diffuse 0.8 }
box { <-2, 0, -3>, <2, 3, 2> inverse pigment { rgb 0.8 } finish { F } }
box { <-2.01, 0, -3>, <-1.99, 3, 2> pigment { rgb <0.8, 0.2, 0.1> } finish { F } }
box { <1.99, 0, -3>, <2.01, 3, 2> pigment { rgb <0.1, 0.3, 0.8> } finish { F } }
sphere { <-0.3, 0.5, 0.4>, 0.5 pigment { rgb <0.9, 0.8, 0.3> } finish { F } }
