// The chi-square distribution's upper tail and its inverse, for media
// sampling methods 1 and 2 (scene/media.h): how many samples an interval
// needs before its variance is believed small enough.
#pragma once

namespace frameray {

// The probability that a chi-square variable with `dof` degrees of freedom
// exceeds x (the upper regularized incomplete gamma Q(dof / 2, x / 2)).
double chiSquareUpperTail(double dof, double x);

// The x whose upper tail is `tail` (0 < tail < 1): the chi-square value
// exceeded with probability `tail`; 0 outside that range.
double chiSquareUpperTailInverse(double dof, double tail);

}  // namespace frameray
