#pragma once
// Time of impact of two circles moving on straight lines during one step.
//
// With d(t) = d0 + t·dd the vector from a to b (t in [0, 1] across the step)
// and s = r_a + r_b, contact starts at the smallest t with |d(t)| = s:
//   (dd·dd) t² + 2 (d0·dd) t + (d0·d0 − s²) = 0.
// Writing A = dd·dd, B = d0·dd, C = d0·d0 − s², the first root is
//   t = (−B − √(B² − A C)) / A  =  C / (−B + √(B² − A C)),
// and the second form is used because it has no cancellation when the balls
// close slowly (A small) and is defined when A = 0.

namespace forcelab::sim {

/// 0 if the circles already overlap at t = 0 (same test as circlesOverlap),
/// the first t in (0, 1] at which they touch, or −1 if they do not touch during
/// the step. NaN input gives −1.
double timeOfImpact(double d0x, double d0y, double ddx, double ddy, double s);

} // namespace forcelab::sim
