// One headless GL context for the whole GL test binary (EGL, else OSMesa), with KHR_debug on:
// every test ends by asserting that the GL recorded no error.
#include <gtest/gtest.h>

#include <cstdio>

#include "gl/context.h"
#include "gl_test_env.h"
#include "tracer_test_util.h"

namespace ssr::test {
gl::HeadlessContext* g_context = nullptr;
}

namespace {

// Writes the images a failed test noted (test::note_images_for_failure); forgets them otherwise.
class WriteImagesOnFailure : public ::testing::EmptyTestEventListener {
  void OnTestStart(const ::testing::TestInfo&) override { ssr::test::noted_images().clear(); }
  void OnTestEnd(const ::testing::TestInfo& info) override {
    if (info.result()->Failed())
      for (const auto& n : ssr::test::noted_images())
        std::fprintf(stderr, "%s: images written to %s\n", info.name(), ssr::test::write_image_pair(n.a, n.b, n.name).c_str());
    ssr::test::noted_images().clear();
  }
};

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::UnitTest::GetInstance()->listeners().Append(new WriteImagesOnFailure);
  if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();  // ctest discovery: no GL
  auto ctx = ssr::gl::HeadlessContext::create(ssr::gl::Backend::Auto, /*debug=*/true);
  std::fprintf(stderr, "GL tests on %s: %s\n", ctx->info().path.c_str(), ctx->info().renderer.c_str());
  ssr::gl::enable_debug_output(/*verbose=*/false);
  ssr::test::g_context = ctx.get();
  const int rc = RUN_ALL_TESTS();
  ssr::test::clear_scored_frames();  // GL objects go before the context does
  return rc;
}
