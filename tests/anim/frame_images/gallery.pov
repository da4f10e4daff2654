// Each frame shows the frames before it: frame N image_maps the image frame
// N - 1 wrote (as the example advanced/desk does with its picture frame),
// so frame N can only be parsed once frame N - 1 is written, whatever the
// frames in flight.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -4> look_at 0 angle 50 }
light_source { <-3, 4, -5> rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
#declare Hue = <(mod(frame_number, 3) = 0), (mod(frame_number, 3) = 1), (mod(frame_number, 3) = 2)>;
sphere { <1.2, -0.6, 0>, 0.6 pigment { rgb Hue * 0.8 + 0.2 } }
#if (frame_number > 1)
  box { <-1.6, -0.2, 0>, <0.4, 1.3, 0.1>
    pigment { image_map { png concat("gallery", str(frame_number - 1, 0, 0), ".png") once }
              scale <2, 1.5, 1> translate <-1.6, -0.2, 0> }
    finish { ambient 1 diffuse 0 }
  }
#end
