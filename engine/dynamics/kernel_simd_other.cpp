// The vectorised contact loops (dynamics/kernel_simd.cpp) for every law that is neither a law of
// the studies (normal part LinearNormal or HertzNormal) nor one with contact dashpots (e.g. the
// cohesive law, contact/linear_cohesive.hpp), in a unit of their own so that the studies' laws'
// code stays as it was without them (see the end of kernel_simd.cpp).
#define DEM_KERNEL_UNIT 2
#include "dynamics/kernel_simd.cpp"
