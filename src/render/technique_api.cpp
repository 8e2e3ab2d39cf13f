#include "render/technique_api.h"

#include <atomic>

namespace ssr {

Technique::Technique() {
  static std::atomic<std::uint64_t> next{1};
  instance_id_ = next++;
}

}  // namespace ssr
