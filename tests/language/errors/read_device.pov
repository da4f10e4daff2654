// Error test: #fopen of a device that never ends (/dev/zero), with the
// file restrictions off. Files are read whole, so anything but a regular
// file is refused before it is opened (a FIFO would block in open).
#version 3.7;
#fopen Zeros "/dev/zero" read
#read (Zeros, Value)
