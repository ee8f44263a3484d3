// Expecting an InputError in tests: the error an action throws, and whether a message holds a
// phrase (with both in the failure's text when it does not).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace coldspray::testing {

// The InputError that `action` throws; a test failure if it throws none.
template <class Action>
InputError input_error(Action&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", "", "");
}

inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

}  // namespace coldspray::testing
