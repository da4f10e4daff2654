// #version needs a number.
#version "3.7";
