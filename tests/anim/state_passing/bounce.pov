// State passing between frames: each frame reads the ball's position and
// velocity that the previous frame wrote to bounce_state.txt, advances
// them one step, writes them back, and draws the ball. The sequence only
// comes out right when frames are parsed in order and every frame sees
// the file its predecessor wrote.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Step = 0.2;
#if (frame_number = initial_frame)
    #declare P = <-2.5, 1.5, 0>;
    #declare V = <1.2, 0, 0>;
#else
    #fopen State "bounce_state.txt" read
    #read (State, P, V)
#end

#declare V = V + <0, -9.8, 0> * Step;
#declare P = P + V * Step;
#if (P.y < -1.2)  // bounce off the floor, losing a fifth of the speed
    #declare P = <P.x, -1.2 - (P.y + 1.2), P.z>;
    #declare V = <V.x, -0.8 * V.y, V.z>;
#end

#fopen Out "bounce_state.txt" write
#write (Out, P, ",", V, "\n")
#fclose Out

camera { location <0, 0, -8> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -10> color rgb 1 }
plane { y, -1.5 pigment { color rgb <0.6, 0.6, 0.55> } }
sphere { P, 0.3 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
