// An image_map whose file does not exist.
#version 3.7;
plane { y, 0 pigment { image_map { png "no_such_image.png" } } }
