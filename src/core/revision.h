// The git revision the binary was built from (`git describe --always --dirty`), or "unknown".
#pragma once
namespace ssr {
const char* build_revision();
}
