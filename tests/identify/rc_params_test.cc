// This test program's rapidcheck defaults (support/rc_params.h): few cases
// per property, a fixed seed.
#include "support/rc_params.h"
