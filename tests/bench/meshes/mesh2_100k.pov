#version 3.7;
global_settings { assumed_gamma 1.0 }
// Benchmark: a wavy mesh2 of ~100 000 smooth triangles (224 x 224 vertices)
// built by #for loops, seen from above with a shadow-casting light. Parse
// (the loops) and render (one BVH over the mesh) are both measured.
#declare N = 224;
camera { location <0, 2.2, -2.6> look_at <0, 0, 0> angle 45 }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.3, 0.4, 0.6> }
#macro H(U, V) (0.08 * sin(U * 23) * cos(V * 19) + 0.05 * sin((U + V) * 31)) #end
mesh2 {
  vertex_vectors { N * N,
    #for (J, 0, N - 1)
      #for (I, 0, N - 1)
        #local U = I / (N - 1); #local V = J / (N - 1);
        <U * 2 - 1, H(U, V), V * 2 - 1>,
      #end
    #end
  }
  face_indices { (N - 1) * (N - 1) * 2,
    #for (J, 0, N - 2)
      #for (I, 0, N - 2)
        #local A = J * N + I;
        <A, A + 1, A + N>, <A + 1, A + N + 1, A + N>,
      #end
    #end
  }
  pigment { color rgb <1, 0.8, 0.5> }
  finish { phong 0.4 }
}
plane { y, -0.3 pigment { color rgb 0.5 } }
