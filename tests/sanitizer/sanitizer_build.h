#pragma once
// Whether this is the sanitizer build (RADVIEW_SANITIZE). There llvmpipe's tessellation runs 30
// to 200 times slower than in Release: a profile is page faults, as ASan's allocator maps every
// large buffer llvmpipe allocates per draw afresh (Mesa's own code is not instrumented). Tests
// that tessellate large meshes draw less there; the Release build draws everything.

namespace radview::test {

#ifdef RADVIEW_SANITIZE
constexpr bool kSanitizerBuild = true;
#else
constexpr bool kSanitizerBuild = false;
#endif

}  // namespace radview::test
