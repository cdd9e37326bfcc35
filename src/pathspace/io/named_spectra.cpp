// The tables behind named_spectra.h. Metals: complex IOR at roughly 650/550/450 nm (the values
// Mitsuba 0.5 and the Bitterli scenes use); approximate, real spectra are smoother than 3 bands.
// Dielectrics: one index per material (no dispersion), as Mitsuba's own IOR table lists them.
#include "pathspace/io/named_spectra.h"

namespace pathspace {

namespace {

struct NamedRgb {
  const char* name;
  Rgb value;
};
const NamedRgb kNamedSpectra[] = {
    {"metal-Cu-eta", {0.200438f, 0.924033f, 1.102212f}}, {"metal-Cu-k", {3.912949f, 2.452848f, 2.142188f}},
    {"metal-Au-eta", {0.143119f, 0.374957f, 1.442479f}}, {"metal-Au-k", {3.983160f, 2.385721f, 1.603215f}},
    {"metal-Ag-eta", {0.155265f, 0.116723f, 0.138342f}}, {"metal-Ag-k", {4.828181f, 3.122249f, 2.146961f}},
    {"metal-Al-eta", {1.657460f, 0.880369f, 0.521229f}}, {"metal-Al-k", {9.223869f, 6.269523f, 4.837001f}},
    {"metal-CuZn-eta", {0.444f, 0.527f, 1.094f}},        {"metal-CuZn-k", {3.695f, 2.765f, 1.829f}},
    {"metal-MgO-eta", {1.732f, 1.738f, 1.752f}},         {"metal-MgO-k", {0.f, 0.f, 0.f}},
    {"metal-TiO2-eta", {2.87f, 2.95f, 3.10f}},           {"metal-TiO2-k", {0.f, 0.f, 0.f}},
    // Glasses: refractive index at the sodium d line (587.6 nm).
    {"glass-BK7", Rgb(1.5168f)}, {"glass-BAF10", Rgb(1.6700f)}, {"glass-FK51A", Rgb(1.4866f)},
    {"glass-LASF9", Rgb(1.8503f)}, {"glass-F5", Rgb(1.6034f)}, {"glass-F10", Rgb(1.6200f)},
    {"glass-F11", Rgb(1.6210f)}, {"glass-SF5", Rgb(1.6727f)}, {"glass-SF10", Rgb(1.7283f)},
    {"glass-SF11", Rgb(1.7847f)},
};

struct NamedIor {
  const char* name;
  float ior;
};
const NamedIor kNamedIors[] = {
    {"vacuum", 1.0f},          {"helium", 1.000036f},       {"hydrogen", 1.000132f}, {"air", 1.000277f},
    {"carbon dioxide", 1.00045f}, {"water", 1.3330f},       {"acetone", 1.36f},      {"ethanol", 1.361f},
    {"carbon tetrachloride", 1.461f}, {"glycerol", 1.4729f}, {"benzene", 1.501f},    {"silicone oil", 1.52045f},
    {"bromine", 1.661f},       {"water ice", 1.31f},        {"fused quartz", 1.458f}, {"pyrex", 1.470f},
    {"acrylic glass", 1.49f},  {"polypropylene", 1.49f},    {"bk7", 1.5046f},        {"sodium chloride", 1.544f},
    {"amber", 1.55f},          {"pet", 1.5750f},            {"diamond", 2.419f},
};

}  // namespace

bool find_named_spectrum(std::string_view name, Rgb* value) {
  for (const NamedRgb& n : kNamedSpectra)
    if (name == n.name) {
      *value = n.value;
      return true;
    }
  return false;
}

bool find_named_ior(std::string_view name, float* ior) {
  for (const NamedIor& n : kNamedIors)
    if (name == n.name) {
      *ior = n.ior;
      return true;
    }
  return false;
}

}  // namespace pathspace
