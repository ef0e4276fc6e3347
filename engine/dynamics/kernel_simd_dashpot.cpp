// The vectorised contact loops (dynamics/kernel_simd.cpp) for the laws with contact dashpots
// (contact/contact_dashpot.hpp), in a unit of their own so that the other laws' code stays as it
// was without them (see the end of kernel_simd.cpp).
#define DEM_KERNEL_UNIT 1
#include "dynamics/kernel_simd.cpp"
