// fuzz_render finding: a ground fog with turbulence, seen along rays that
// miss everything, evaluates noise 1e7 units out: the lattice index
// conversion overflowed int (undefined behaviour).
camera { location <0, 0, -10> look_at 0 }
plane { y, -2 pigment { rgb 1 } }
fog { fog_type 2 distance 300 fog_offset 0.1 fog_alt 1.5 turbulence 1.8 rgb 0.5 }
