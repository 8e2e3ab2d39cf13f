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

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (::testing::GTEST_FLAG(list_tests)) return RUN_ALL_TESTS();  // ctest discovery: no GL
  auto ctx = ssr::gl::HeadlessContext::create(ssr::gl::Backend::Auto, /*debug=*/true);
  std::fprintf(stderr, "GL tests on %s: %s\n", ctx->info().path.c_str(), ctx->info().renderer.c_str());
  ssr::gl::enable_debug_output(/*verbose=*/false);
  ssr::test::g_context = ctx.get();
  const int rc = RUN_ALL_TESTS();
  ssr::test::clear_scored_frames();  // GL objects go before the context does
  return rc;
}
