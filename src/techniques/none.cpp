// `none`: no reflection work at all. Confidence 0 everywhere, so the composite shows the
// environment: the baseline every other technique is measured against.
#include "techniques/screen_pass.h"

namespace ssr {

std::unique_ptr<Technique> make_none_technique() {
  return std::make_unique<ScreenPassTechnique>("none", "techniques/none.comp", kReadGBuffer);
}

}  // namespace ssr
