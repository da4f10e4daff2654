// povray 3.7 refuses an image_map in a normal ("can only be used in a
// pigment statement"); frameray used to read the image and ignore it.
#version 3.7;
sphere { 0, 1 normal { image_map { png "missing.png" } } }
