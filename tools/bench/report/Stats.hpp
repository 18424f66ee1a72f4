#pragma once
// Order statistics of a benchmark's samples (frame times, run times).
//
//   const double p95 = percentile(frameMs, 95);   // frameMs left as it is
//   const double mid = median(frameMs);           // = percentile(frameMs, 50)
//
// percentile(v, p) interpolates linearly between the two closest ranks
// (NumPy's default, Excel's PERCENTILE.INC): p = 0 is the minimum, 100 the
// maximum, and the median of an even count is the mean of the middle two.
// With no samples there is no such value: both return NaN, which BenchJson
// writes as null (a 0 would read as an impossibly fast run). Samples must
// not be NaN.

#include <span>

namespace arcomp {

// p in 0..100; std::invalid_argument outside.
double percentile(std::span<const double> samples, double p);
double median(std::span<const double> samples);

}  // namespace arcomp
