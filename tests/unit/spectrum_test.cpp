// Spectra into RGB (src/pathspace/io/spectrum/): closed forms (a constant reflectance stays grey,
// an illuminant has luminance 1, a blackbody lies on the Planckian locus), gold's measured .spd
// files against the named metal-Au spectra, .spd errors with their location, and spectra in pbrt
// and Mitsuba scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "pathspace/io/mitsuba/mitsuba_loader.h"
#include "pathspace/io/named_spectra.h"
#include "pathspace/io/scene_loader.h"
#include "pathspace/io/spectrum/spectrum_to_rgb.h"
#include "pathspace/io/spectrum/white_balance.h"
#include "support/temp_dir.h"

namespace pathspace {
namespace {

using pathspace::testing::TempDir;

const std::string kSpectra = std::string(PATHSPACE_TEST_DATA_DIR) + "/spectra";

struct Xy {
  double x, y;
};

// CIE xy of a linear sRGB colour (the inverse of xyz_to_linear_srgb's matrix).
Xy chromaticity(const Rgb& c) {
  const double x = 0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b;
  const double y = 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b;
  const double z = 0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b;
  return {x / (x + y + z), y / (x + y + z)};
}

// The Planckian locus in CIE 1931 xy, Kim et al. 2002's cubic splines (1667 K to 25000 K), which
// follow Planck's law integrated against the CIE 1931 observer to about 1e-4.
Xy planckian_locus(double t) {
  const double x = t <= 4000 ? -0.2661239e9 / (t * t * t) - 0.2343589e6 / (t * t) + 0.8776956e3 / t + 0.179910
                             : -3.0258469e9 / (t * t * t) + 2.1070379e6 / (t * t) + 0.2226347e3 / t + 0.240390;
  const double y = t <= 2222   ? -1.1063814 * x * x * x - 1.34811020 * x * x + 2.18555832 * x - 0.20219683
                   : t <= 4000 ? -0.9549476 * x * x * x - 1.37418593 * x * x + 2.09137015 * x - 0.16748867
                               : 3.0817580 * x * x * x - 5.87338670 * x * x + 3.75112997 * x - 0.37001483;
  return {x, y};
}

SampledSpectrum constant(double value) { return spectrum_from_pairs({300.0, value, 900.0, value}, {}, "test"); }

TEST(Spectrum, ConstantReflectanceStaysGrey) {
  for (double c : {0.05, 0.5, 1.0}) {
    const Rgb rgb = spectrum_to_rgb(constant(c), SpectrumUse::reflectance);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(rgb[i], c, 1e-3 * c) << "c = " << c << ", channel " << i;
  }
}

TEST(Spectrum, IlluminantsHaveLuminanceOne) {
  for (double t : {1000.0, 2000.0, 2856.0, 4000.0, 6504.0, 10000.0, 40000.0}) {
    const Rgb rgb = spectrum_to_rgb(blackbody_spectrum(t, BlackbodyUnit::peak_normalised, {}), SpectrumUse::illuminant);
    EXPECT_NEAR(luminance(rgb), 1.f, 1e-4f) << t << " K";
  }
  // A scaled spectrum is the same colour: the light's scale, not its spectrum, sets the magnitude.
  const Rgb a = spectrum_to_rgb(constant(1.0), SpectrumUse::illuminant);
  const Rgb b = spectrum_to_rgb(constant(1234.0), SpectrumUse::illuminant);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-6f);
  EXPECT_EQ(spectrum_to_rgb(constant(0.0), SpectrumUse::illuminant), Rgb(0.f));
}

TEST(Spectrum, BlackbodyLiesOnThePlanckianLocus) {
  for (double t : {2000.0, 3000.0, 4000.0, 5000.0, 6504.0, 10000.0, 20000.0}) {
    const Xy got = chromaticity(spectrum_to_rgb(blackbody_spectrum(t, BlackbodyUnit::peak_normalised, {}), SpectrumUse::illuminant));
    const Xy want = planckian_locus(t);
    EXPECT_NEAR(got.x, want.x, 1e-3) << t << " K";
    EXPECT_NEAR(got.y, want.y, 1e-3) << t << " K";
  }
  // 6504 K is not D65 (0.3127, 0.3290): the blackbody lies 0.0054 below it in y, so in sRGB it is
  // magenta by up to 4% against white (docs/conventions.md, "Spectra").
  const Rgb rgb = spectrum_to_rgb(blackbody_spectrum(6504.0, BlackbodyUnit::peak_normalised, {}), SpectrumUse::illuminant);
  EXPECT_NEAR(rgb.r, 1.043f, 0.005f);
  EXPECT_NEAR(rgb.g, 0.984f, 0.005f);
  EXPECT_NEAR(rgb.b, 1.036f, 0.005f);
}

TEST(Spectrum, BlackbodyUnits) {
  // Peak-normalised (pbrt-v4): 1 at Wien's peak, 500 nm at 5795.5 K; below 1 elsewhere.
  const double t = 2.897771955e-3 / 500e-9;
  const SampledSpectrum s = blackbody_spectrum(t, BlackbodyUnit::peak_normalised, {});
  EXPECT_NEAR(s.at(500.0), 1.0, 1e-9);
  for (double v : s.value) EXPECT_LE(v, 1.0 + 1e-12);
  // Spectral radiance (Mitsuba): Planck's law at 500 nm, 5795.5 K, in W / (m^2 sr nm).
  const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23, l = 500e-9;
  const double planck = 2 * h * c * c / std::pow(l, 5) / std::expm1(h * c / (l * k * t)) * 1e-9;
  EXPECT_NEAR(blackbody_spectrum(t, BlackbodyUnit::radiance_per_nm, {}).at(500.0) / planck, 1.0, 1e-9);
  EXPECT_THROW(blackbody_spectrum(0.0, BlackbodyUnit::peak_normalised, {}), Error);
  EXPECT_THROW(blackbody_spectrum(std::nan(""), BlackbodyUnit::peak_normalised, {}), Error);
}

TEST(Spectrum, PiecewiseLinearAndZeroOutside) {
  const SampledSpectrum s = spectrum_from_pairs({400, 1, 500, 3, 600, 2}, {}, "test");
  EXPECT_DOUBLE_EQ(s.at(400), 1);
  EXPECT_DOUBLE_EQ(s.at(450), 2);
  EXPECT_DOUBLE_EQ(s.at(550), 2.5);
  EXPECT_DOUBLE_EQ(s.at(600), 2);
  EXPECT_DOUBLE_EQ(s.at(399.9), 0);
  EXPECT_DOUBLE_EQ(s.at(600.1), 0);
  EXPECT_THROW(spectrum_from_pairs({400, 1, 500}, {}, "odd"), Error);
  EXPECT_THROW(spectrum_from_pairs({500, 1, 400, 2}, {}, "decreasing"), Error);
  EXPECT_THROW(spectrum_from_pairs({}, {}, "empty"), Error);
}

// pbrt-v4's measured gold, read from .spd files, gives the named spectra's RGB (the unbounded
// conversion is the named table's convention) within 1% per channel.
TEST(Spectrum, GoldSpdFilesMatchTheNamedSpectra) {
  const struct {
    const char* file;
    const char* named;
  } cases[] = {{"Au.eta.spd", "metal-Au-eta"}, {"Au.k.spd", "metal-Au-k"}};
  for (const auto& c : cases) {
    const Rgb got = spectrum_to_rgb(read_spd_file(kSpectra + "/" + c.file), SpectrumUse::unbounded);
    Rgb named;
    ASSERT_TRUE(find_named_spectrum(c.named, &named));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i] / named[i], 1.f, 0.01f) << c.file << " channel " << i;
  }
}

TEST(Spectrum, SpdErrorsCarryTheirLocation) {
  const TempDir temp("spd");
  const std::string bad = (temp.path / "bad.spd").string();
  std::ofstream(bad) << "# comment\n400 0.5\n500 oops\n";
  try {
    read_spd_file(bad);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.location().file, bad);
    EXPECT_EQ(e.location().line, 3);
    EXPECT_EQ(e.location().column, 5);
  }
  const std::string odd = (temp.path / "odd.spd").string();
  std::ofstream(odd) << "400 0.5 500\n";
  EXPECT_THROW(read_spd_file(odd), Error);
  EXPECT_THROW(read_spd_file((temp.path / "missing.spd").string()), Error);
}

TEST(Spectrum, PbrtScenesReadSpectra) {
  const TempDir temp("pbrt-spectra");
  std::ofstream(temp.path / "Au.eta.spd") << std::ifstream(kSpectra + "/Au.eta.spd").rdbuf();
  std::ofstream(temp.path / "Au.k.spd") << std::ifstream(kSpectra + "/Au.k.spd").rdbuf();
  const std::string main = (temp.path / "scene.pbrt").string();
  std::ofstream(main) << "Camera \"perspective\"\nWorldBegin\n"
                         "LightSource \"point\" \"blackbody I\" [ 3000 ] \"float scale\" 2\n"
                         "LightSource \"point\" \"spectrum I\" \"stdillum-D65\"\n"
                         "Material \"conductor\" \"spectrum eta\" \"Au.eta.spd\" \"spectrum k\" \"Au.k.spd\"\n"
                         "Shape \"sphere\"\n"
                         "Material \"diffuse\" \"spectrum reflectance\" [ 350 0.25 850 0.25 ]\n"
                         "Shape \"sphere\" \"float radius\" 0.5\n";
  std::vector<std::string> warnings;
  const Scene s = load_scene(main, {}, &warnings);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_NEAR(luminance(s.lights[0].value), 2.f, 2e-4f);
  const Xy bb = chromaticity(s.lights[0].value), locus = planckian_locus(3000);
  EXPECT_NEAR(bb.x, locus.x, 1e-3);
  EXPECT_NEAR(bb.y, locus.y, 1e-3);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.lights[1].value[i], 1.f, 2e-3f);
  ASSERT_EQ(s.spheres.size(), 2u);
  Rgb eta, k;
  find_named_spectrum("metal-Au-eta", &eta);
  find_named_spectrum("metal-Au-k", &k);
  const Material& gold = s.materials[s.spheres[0].material];
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(gold.eta[i] / eta[i], 1.f, 0.01f);
    EXPECT_NEAR(gold.k[i] / k[i], 1.f, 0.01f);
    EXPECT_NEAR(s.materials[s.spheres[1].material].diffuse[i], 0.25f, 1e-3f);
  }
  EXPECT_TRUE(warnings.empty()) << warnings.front();

  std::ofstream(main) << "Camera \"perspective\"\nWorldBegin\nMaterial \"conductor\" \"spectrum eta\" \"nowhere.spd\"\n"
                         "Shape \"sphere\"\n";
  try {
    load_scene(main, {}, nullptr);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.location().line, 3);
    EXPECT_NE(std::string(e.what()).find("nowhere.spd"), std::string::npos);
  }
}

TEST(Spectrum, MitsubaScenesReadSpectra) {
  const std::string xml =
      "<scene version=\"3.0.0\">\n"
      "<bsdf type=\"conductor\" id=\"gold\"><spectrum name=\"eta\" filename=\"Au.eta.spd\"/>"
      "<spectrum name=\"k\" filename=\"Au.k.spd\"/></bsdf>\n"
      "<shape type=\"sphere\"><ref id=\"gold\"/></shape>\n"
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><spectrum name=\"reflectance\" value=\"360:0.5, 830:0.5\"/></bsdf></shape>\n"
      "<emitter type=\"point\"><blackbody name=\"intensity\" temperature=\"5000K\" scale=\"1e-4\"/></emitter>\n"
      "</scene>\n";
  std::vector<std::string> warnings;
  LoadWarnings w(&warnings);
  const Scene s = mitsuba::load_mitsuba_string(xml, "scene.xml", kSpectra, {}, &w, nullptr);
  ASSERT_EQ(s.spheres.size(), 2u);
  Rgb eta;
  find_named_spectrum("metal-Au-eta", &eta);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(s.materials[s.spheres[0].material].eta[i] / eta[i], 1.f, 0.01f);
    EXPECT_NEAR(s.materials[s.spheres[1].material].diffuse[i], 0.5f, 1e-3f);
  }
  ASSERT_EQ(s.lights.size(), 1u);
  // Planck's law in W / (m^2 sr nm) has luminance Y = integral of B y-bar / integral of y-bar.
  const Xy bb = chromaticity(s.lights[0].value), locus = planckian_locus(5000);
  EXPECT_NEAR(bb.x, locus.x, 1e-3);
  EXPECT_NEAR(bb.y, locus.y, 1e-3);
  const SampledSpectrum planck = blackbody_spectrum(5000, BlackbodyUnit::radiance_per_nm, {});
  EXPECT_NEAR(luminance(s.lights[0].value) / (1e-4 * y_bar_weighted_mean(planck)), 1.0, 1e-3);
}

// pbrt-v4's film white balance: CIE daylight's chromaticity, and the Bradford adaptation that takes
// that white to D65's.
TEST(WhiteBalance, DaylightChromaticityAndAdaptation) {
  const std::array<double, 2> d65 = daylight_chromaticity(6504.0);
  EXPECT_NEAR(d65[0], 0.31271, 2e-4);  // CIE 015's D65
  EXPECT_NEAR(d65[1], 0.32902, 2e-4);
  const std::array<float, 9> near_identity = white_balance_matrix(6504.0);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(near_identity[i], i % 4 == 0 ? 1.f : 0.f, 2e-3f) << i;
  for (const double t : {4000.0, 5000.0, 9000.0, 20000.0}) {
    const std::array<double, 2> xy = daylight_chromaticity(t);
    const Rgb white = xyz_to_linear_srgb(xy[0] / xy[1], 1.0, (1.0 - xy[0] - xy[1]) / xy[1]);
    const std::array<float, 9> m = white_balance_matrix(t);
    for (int row = 0; row < 3; ++row)
      EXPECT_NEAR(m[3 * row] * white.r + m[3 * row + 1] * white.g + m[3 * row + 2] * white.b, 1.f, 1e-3f) << t << " K, row " << row;
  }
  const std::array<float, 9> none = white_balance_matrix(0.0);
  for (int i = 0; i < 9; ++i) EXPECT_EQ(none[i], i % 4 == 0 ? 1.f : 0.f);
  EXPECT_THROW(white_balance_matrix(3000.0), Error);
}

}  // namespace
}  // namespace pathspace
