#include "pathspace/options/option_parse.h"

#include <charconv>
#include <cmath>
#include <system_error>

#include "pathspace/options/option_spec.h"

namespace pathspace {

namespace {

template <typename T>
T parse_real(const std::string& name, const std::string& text, double min, double max) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec == std::errc::invalid_argument || ptr != end)
    throw OptionError(option_message(name, text, "expects a number"));
  if (ec == std::errc::result_out_of_range || !std::isfinite(value))
    throw OptionError(option_message(name, text, "expects a finite number"));
  if (double(value) < min || double(value) > max)
    throw OptionError(option_message(name, text, "must be between " + number_text(min) + " and " + number_text(max)));
  return value;
}

template <typename T>
std::string shortest(T value) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof(buf), value);
  return ec == std::errc() ? std::string(buf, ptr) : std::string("?");
}

}  // namespace

std::string option_message(const std::string& name, const std::string& text, const std::string& problem) {
  return "--" + name + " '" + text + "': " + problem;
}

int64_t parse_integer_option(const std::string& name, const std::string& text, double min, double max) {
  int64_t value = 0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (begin == end || ec == std::errc::invalid_argument || ptr != end)
    throw OptionError(option_message(name, text, "expects a whole number"));
  if (ec == std::errc::result_out_of_range || double(value) < min || double(value) > max)
    throw OptionError(option_message(name, text, "must be between " + number_text(min) + " and " + number_text(max)));
  return value;
}

uint64_t parse_unsigned_option(const std::string& name, const std::string& text, uint64_t max) {
  uint64_t value = 0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const bool negative = begin != end && *begin == '-';
  const auto [ptr, ec] = std::from_chars(negative ? begin + 1 : begin, end, value);
  if (begin == end || ec == std::errc::invalid_argument || ptr != end)
    throw OptionError(option_message(name, text, "expects a whole number"));
  if (negative || ec == std::errc::result_out_of_range || value > max)
    throw OptionError(option_message(name, text, "must be between 0 and " + std::to_string(max)));
  return value;
}

float parse_float_option(const std::string& name, const std::string& text, double min, double max) {
  return parse_real<float>(name, text, min, max);
}

double parse_double_option(const std::string& name, const std::string& text, double min, double max) {
  return parse_real<double>(name, text, min, max);
}

std::string number_text(double value) {
  if (value == std::floor(value) && std::fabs(value) < 1e15) return shortest(int64_t(value));
  return shortest(value);
}
std::string number_text(float value) {
  if (value == std::floor(value) && std::fabs(value) < 1e7f) return shortest(int64_t(value));
  return shortest(value);
}
std::string number_text(int64_t value) { return shortest(value); }

}  // namespace pathspace
