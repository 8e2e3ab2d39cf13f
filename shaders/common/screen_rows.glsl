// Screen passes that cover several pixel rows per invocation (gl::Program::dispatch_2d divides
// its groups by SSR_ROWS). The floor pass does its traffic a fifth faster with two rows on the
// H200; the techniques' passes were slower that way (docs/RESULTS.md), so only it uses this.
#ifndef SSR_ROWS
#define SSR_ROWS 1
#endif

// The invocation's r-th pixel, r < SSR_ROWS: a group covers local_size_x by local_size_y *
// SSR_ROWS pixels, row block by row block, so each step reads the same block shape as one
// pixel per invocation did. (A macro: gl_WorkGroupSize exists only after the pass's layout.)
#define screen_pixel(r)                                                                   \
  ivec2(int(gl_GlobalInvocationID.x),                                                      \
        (int(gl_WorkGroupID.y) * SSR_ROWS + (r)) * int(gl_WorkGroupSize.y) + int(gl_LocalInvocationID.y))
