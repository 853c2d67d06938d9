// FRICTION_ASSERT: internal invariants, checked in debug builds only. User input
// is never checked with it: that is InputError's job.
#pragma once

#include <cassert>

#ifdef NDEBUG
#define FRICTION_ASSERT(cond, msg) ((void)0)
#else
#define FRICTION_ASSERT(cond, msg) assert((cond) && (msg))
#endif
