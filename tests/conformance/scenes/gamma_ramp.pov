// Conformance: output encoding. Flat patches of known linear values
// (ambient 1, diffuse 0, so the light plays no part) pin down the transfer
// function to 8 bits: with assumed_gamma 1.0 POV-Ray 3.7 writes sRGB-encoded
// PNGs, and the darkest patches differ by up to 8/255 between the sRGB curve
// and a plain 2.2 power law. The bottom row is diffusely lit by an
// over-bright light so it also checks per-channel clipping. The camera
// frames exactly 16 x 12 units at z = 0, so every patch edge falls on a
// pixel boundary (pixels are 0.05 units) rather than near a pixel centre;
// the boxes are thin so their sides stay well inside one pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 0, -12>
    direction z
    right x * 4 / 3
    up y
}

light_source { <-2, -3, -6> color rgb <1.8, 1.8, 1.8> }

#declare Unlit = finish { ambient 1 diffuse 0 }

// Top row: very dark values, where sRGB and gamma 2.2 disagree most.
box { <-7.6, 2.1, 0>, <-4.1, 5.7, 0.01> pigment { color rgb <0.0005, 0.001, 0.002> } finish { Unlit } }
box { <-3.7, 2.1, 0>, <-0.2, 5.7, 0.01> pigment { color rgb <0.003, 0.005, 0.008> } finish { Unlit } }
box { <0.2, 2.1, 0>, <3.7, 5.7, 0.01> pigment { color rgb <0.01, 0.015, 0.02> } finish { Unlit } }
box { <4.1, 2.1, 0>, <7.6, 5.7, 0.01> pigment { color rgb <0.03, 0.05, 0.08> } finish { Unlit } }

// Middle row: mid tones up to full white.
box { <-7.6, -1.8, 0>, <-4.1, 1.8, 0.01> pigment { color rgb <0.1, 0.15, 0.2> } finish { Unlit } }
box { <-3.7, -1.8, 0>, <-0.2, 1.8, 0.01> pigment { color rgb <0.25, 0.3, 0.4> } finish { Unlit } }
box { <0.2, -1.8, 0>, <3.7, 1.8, 0.01> pigment { color rgb <0.5, 0.6, 0.7> } finish { Unlit } }
box { <4.1, -1.8, 0>, <7.6, 1.8, 0.01> pigment { color rgb <0.8, 0.9, 1.0> } finish { Unlit } }

// Bottom row: lit, smooth falloff across each patch; the brightest parts
// exceed 1 in some channels and must clip.
box { <-7.6, -5.7, 0>, <-4.1, -2.1, 0.01> pigment { color rgb <1, 0.5, 0.2> } finish { ambient 0 diffuse 1 } }
box { <-3.7, -5.7, 0>, <-0.2, -2.1, 0.01> pigment { color rgb <0.2, 0.9, 0.4> } finish { ambient 0 diffuse 0.8 } }
box { <0.2, -5.7, 0>, <3.7, -2.1, 0.01> pigment { color rgb <0.3, 0.4, 1> } finish { ambient 0.05 diffuse 0.6 } }
box { <4.1, -5.7, 0>, <7.6, -2.1, 0.01> pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 0 diffuse 0.5 phong 0.6 phong_size 8 } }
