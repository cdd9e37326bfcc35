#include "distinct_files.h"

#include "pathspace/io/file_identity.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::cli {

void check_distinct_files(const std::vector<NamedFile>& outputs, const std::vector<NamedFile>& inputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedFile& out = outputs[i];
    for (size_t j = i + 1; j < outputs.size(); ++j)
      if (same_file(out.path, outputs[j].path))
        throw UsageError(out.option + " '" + out.path + "' and " + outputs[j].option + " '" + outputs[j].path +
                         "' name one file: each output needs its own");
    for (const NamedFile& in : inputs)
      if (same_file(out.path, in.path))
        throw UsageError(out.option + " '" + out.path + "' would overwrite the input '" + in.path + "' (" + in.option + ")");
  }
}

}  // namespace pathspace::cli
