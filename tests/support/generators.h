#pragma once
/// The one header of rapidcheck generators for lpvid tests (docs/design.md §13.8).
/// Objects are built by construction (no rejection sampling) and sized by
/// rapidcheck's size parameter so that shrinking finds tiny counterexamples.
/// Each area keeps its generators in a gen_*.h file included from here.

#include "support/gen_numbers.h"
#include "support/gen_models.h"
#include "support/gen_files.h"
#include "support/gen_lmi.h"
#include "support/gen_matrices.h"
#include "support/gen_identify.h"
