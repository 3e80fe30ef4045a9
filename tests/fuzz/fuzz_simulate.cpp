// libFuzzer entry point: the simulator on a loaded setup (FuzzTargets.h).
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    return cuelab::fuzz::fuzzSimulator(data, size);
}
