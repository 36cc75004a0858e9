// libFuzzer entry point; run_fuzz.sh compiles it once per target with
// -DVICC_FUZZ_TARGET=<harness function>.
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return vicc_anatomy_viz::fuzz::VICC_FUZZ_TARGET(data, size);
}
