// Checks of the one-sentence InputError messages, shared by the unit tests.
#pragma once
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.h"

namespace ssr::test {

// The message of the InputError `f` throws; a test failure when it throws nothing or another type.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected ssr::InputError, got another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected ssr::InputError, nothing was thrown";
  return {};
}

// One sentence: no line break, ends with a full stop, contains every expected fragment.
inline void expect_message(const std::string& msg, const std::vector<std::string>& fragments) {
  ASSERT_FALSE(msg.empty());
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  EXPECT_EQ(msg.back(), '.') << msg;
  for (const std::string& f : fragments)
    EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
}

}  // namespace ssr::test
