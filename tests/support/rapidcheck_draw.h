#pragma once
/// The RandomDraw of the library generators (examples/random_case.h) over
/// rapidcheck: inside rc::gen::exec or a property each draw is a rapidcheck
/// value, so cases replay from rapidcheck's seed and shrink. Integers are
/// uniform whatever the size (the generators' ranges are already small) and
/// shrink towards lo; coins shrink towards false.

#include <rapidcheck.h>

#include "examples/random_case.h"

namespace lpvid::gen {

class RapidcheckDraw final : public RandomDraw {
 public:
  int integer(int lo, int hi) override { return *rc::gen::resize(100, rc::gen::inRange(lo, hi + 1)); }
  bool coin() override { return *rc::gen::arbitrary<bool>(); }
};

/// The generator that runs a library draw function `f(RandomDraw&)` on
/// rapidcheck's draws.
template <typename F>
auto drawn(F f) {
  return rc::gen::exec([f] {
    RapidcheckDraw d;
    return f(d);
  });
}

}  // namespace lpvid::gen
