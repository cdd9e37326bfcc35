// pbrt-v4 parser: turns the token stream into Statements and follows Include / Import (also
// gzip-compressed files) itself, so the scene builder sees one flat statement sequence. Syntax
// errors are pathspace::Error with file:line:column.
#pragma once

#include <functional>
#include <string>

#include "pathspace/io/pbrt/pbrt_statement.h"

namespace pathspace::pbrt {

using StatementHandler = std::function<void(const Statement&)>;

// Parses a scene file. Relative Include/Import paths are resolved against the including file's
// folder, then against the main file's folder (pbrt-v4 resolves against the latter).
void parse_file(const std::string& path, const StatementHandler& handler);
// Parses text; `name` is used in locations and `folder` resolves relative includes.
void parse_string(const std::string& text, const std::string& name, const std::string& folder,
                  const StatementHandler& handler);

}  // namespace pathspace::pbrt
