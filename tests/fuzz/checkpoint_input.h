// Byte-level entry point of the checkpoint reader, shared by the libFuzzer target
// (fuzz_checkpoint.cpp) and the corpus replay (unit/checkpoint_fuzz_replay_test.cpp).
// Contract for every input: restoring it returns true (a checkpoint, or a bare session state, that
// one of the seven reference sessions accepted) or throws pathspace::Error; any other exception, a
// crash or a sanitizer report is a finding.
//
// The reference sessions are the built-in Cornell box at 8x8, seed 0, default options, one per
// integrator and filter (pt, pt + hashed filter, pt + consistent filter, lt, bpt, sppm, pclt): the
// corpus holds checkpoints of those
// (`pathspace render cornell-box -r 8x8 -s 2 -i NAME --checkpoint FILE`). Input that starts like a
// bare session state (base/state_archive.h) is restored without the file container, so that the
// fuzzer reaches the state reader behind the checksum.
#pragma once

#include <string_view>

namespace pathspace::fuzz {

bool restore_checkpoint_bytes(std::string_view bytes);

}  // namespace pathspace::fuzz
