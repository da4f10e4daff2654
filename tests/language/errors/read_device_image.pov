// Error test: an image map read from a device (/dev/zero), with the file
// restrictions off: refused, not read forever.
#version 3.7;
sphere { 0, 1 pigment { image_map { png "/dev/zero" } } }
