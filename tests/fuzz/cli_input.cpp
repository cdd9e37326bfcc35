#include "fuzz/cli_input.h"

#include "cli_app.h"
#include "pathspace/options/option_spec.h"
#include "pathspace/options/usage_error.h"

namespace pathspace::fuzz {

std::vector<std::string> cli_words(std::string_view bytes) {
  constexpr size_t kMaxWords = 48, kMaxWordBytes = 512;
  std::vector<std::string> words;
  size_t start = 0;
  while (start <= bytes.size() && words.size() < kMaxWords) {
    size_t end = bytes.find('\0', start);
    if (end == std::string_view::npos) end = bytes.size();
    words.emplace_back(bytes.substr(start, std::min(end - start, kMaxWordBytes)));
    start = end + 1;
  }
  return words;
}

std::string parse_cli_words(const std::vector<std::string>& words) {
  std::vector<std::string> storage;
  storage.reserve(words.size() + 1);
  storage.push_back("pathspace");
  storage.insert(storage.end(), words.begin(), words.end());
  std::vector<char*> argv;
  for (std::string& w : storage) argv.push_back(w.data());
  argv.push_back(nullptr);
  cli::CliApp cli;
  try {
    cli.parse(int(storage.size()), argv.data());
    if (cli.render_cmd->parsed()) cli::check_render_options(cli.render_options, *cli.render_cmd);
    return "parsed";
  } catch (const CLI::CallForHelp&) {
    return "help";
  } catch (const CLI::CallForAllHelp&) {
    return "help";
  } catch (const CLI::ParseError&) {
    return "usage";
  } catch (const UsageError&) {
    return "usage";
  } catch (const OptionError&) {
    return "usage";
  }
}

}  // namespace pathspace::fuzz
