// libFuzzer entry point: the setup loader (FuzzTargets.h).
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    return cuelab::fuzz::fuzzSetupLoader(data, size);
}
