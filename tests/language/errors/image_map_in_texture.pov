// povray 3.7 refuses an image_map in a texture ("can only be used in a
// pigment statement"); after a pattern, frameray used to read the image
// and ignore it.
#version 3.7;
sphere { 0, 1 texture { checker image_map { png "missing.png" } } }
