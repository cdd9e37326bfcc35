// Strict text -> value conversions shared by every OptionTable: the whole text must be one finite
// number (no trailing characters, no NaN or infinity, no wrap-around), and text for messages.
#pragma once

#include <cstdint>
#include <string>

namespace pathspace {

// "--name text: what went wrong" for OptionError messages.
std::string option_message(const std::string& name, const std::string& text, const std::string& problem);

// Whole numbers; throws OptionError (naming --name) when text is not one or lies outside [min, max].
int64_t parse_integer_option(const std::string& name, const std::string& text, double min, double max);
// Whole numbers 0 ... max for 64-bit unsigned fields (seeds): "-1" is out of range, never wrapped.
uint64_t parse_unsigned_option(const std::string& name, const std::string& text, uint64_t max);
// Finite reals, parsed directly into the field's precision.
float parse_float_option(const std::string& name, const std::string& text, double min, double max);
double parse_double_option(const std::string& name, const std::string& text, double min, double max);

// Shortest text that reads back as the same value ("0.6666667", "12", "1e+30").
std::string number_text(double value);
std::string number_text(float value);
std::string number_text(int64_t value);

}  // namespace pathspace
