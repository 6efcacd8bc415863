#pragma once
/// Test helpers for bad-input tests: the message of the InputError a call
/// throws (a test failure if it throws none), and substring search.

#include <string>

#include <gtest/gtest.h>

#include "core/input_error.h"

namespace lpvid::gen {

template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return "";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace lpvid::gen
