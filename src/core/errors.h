// Error types shared by every part of ssrlab.
//
// InputError: the user gave us something wrong (a file, a flag, a value). The CLI turns it into
// one sentence on stderr and exit code 2. RuntimeError: the machine or the GL failed; exit 1.
#pragma once
#include <stdexcept>
#include <string>

namespace ssr {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RuntimeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace ssr
