// Screen passes that cover several pixel rows per invocation (gl::Program::dispatch_2d divides
// its groups by SSR_ROWS). A full-screen pass on the H200 costs about 0.025 ms at 1080p before
// any work, and that floor follows the invocation count (docs/RESULTS.md).
#ifndef SSR_ROWS
#define SSR_ROWS 1
#endif

// The invocation's r-th pixel, r < SSR_ROWS: a group covers local_size_x by local_size_y *
// SSR_ROWS pixels, row block by row block, so each step reads the same block shape as one
// pixel per invocation did. (A macro: gl_WorkGroupSize exists only after the pass's layout.)
#define screen_pixel(r)                                                                   \
  ivec2(int(gl_GlobalInvocationID.x),                                                      \
        (int(gl_WorkGroupID.y) * SSR_ROWS + (r)) * int(gl_WorkGroupSize.y) + int(gl_LocalInvocationID.y))
