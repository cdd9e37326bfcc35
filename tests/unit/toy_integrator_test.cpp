// Adding an integrator needs only its own file: this file defines a toy integrator (the shading
// normal of the first hit as colour, n * 0.5 + 0.5, times --toy-scale), registers it with an
// IntegratorRegistrar and an OptionTable of one option, and renders it through a RenderSession and
// through configure_render() as the CLI does. Nothing else in the project knows about it.
#include <gtest/gtest.h>

#include <algorithm>
#include <any>
#include <memory>
#include <string>

#include "pathspace/accel/accel.h"
#include "pathspace/integrators/common/camera_sample.h"
#include "pathspace/integrators/integrator.h"
#include "pathspace/integrators/integrator_registry.h"
#include "pathspace/options/option_table.h"
#include "pathspace/parallel/parallel_for.h"
#include "pathspace/scene/scene.h"
#include "pathspace/scene/scene_view.h"
#include "pathspace/session/render.h"
#include "pathspace/session/render_config.h"
#include "pathspace/session/render_session.h"
#include "support/test_scenes.h"

namespace pathspace {
namespace {

struct ToySettings {
  float scale = 1.f;
};

class ToyIntegrator final : public Integrator {
 public:
  ToyIntegrator(const Scene& scene, const Accel& accel, const ToySettings& settings, uint64_t seed)
      : view_(scene.view()), accel_(accel), settings_(settings), seed_(seed) {}
  const char* name() const override { return "toy"; }

  void render_pass(uint32_t pass, Film& film, PathCounters& counters) override {
    const size_t n = film.pixel_count();
    parallel_for(n, 64, [&](size_t begin, size_t end) {
      for (size_t pixel = begin; pixel < end; ++pixel) {
        const Sampler sampler(seed_, pixel, pass);
        SurfaceHit hit;
        Rgb value;
        if (accel_.intersect(sample_camera_ray(view_.camera, sampler, uint32_t(pixel), 0.f), &hit))
          value = Rgb(hit.ns.x * 0.5f + 0.5f, hit.ns.y * 0.5f + 0.5f, hit.ns.z * 0.5f + 0.5f) * settings_.scale;
        film.add_sample(uint32_t(pixel), value);
      }
    });
    counters.rays += n;
    counters.paths += n;
    ++passes_;
  }

  void statistics(Statistics& out) const override { out.counter("toy.passes", passes_); }
  void save_state(StateWriter& out) const override { out.put("toy.passes", passes_); }
  void load_state(StateReader& in) override { in.get("toy.passes", &passes_); }

 private:
  SceneView view_;
  const Accel& accel_;
  ToySettings settings_;
  uint64_t seed_;
  uint64_t passes_ = 0;
};

OptionTable<ToySettings> toy_options() {
  OptionTable<ToySettings> t;
  t.number("toy-scale", &ToySettings::scale, 0.0, 100.0, "Brightness of the normal colours");
  return t;
}

const IntegratorRegistrar kToyRegistrar{make_integrator_entry<ToySettings>(
    "toy", "shading normals as colours (a test of the registry)", "none", toy_options(), {},
    [](const IntegratorContext& ctx, const ToySettings& s) -> std::unique_ptr<Integrator> {
      return std::make_unique<ToyIntegrator>(ctx.scene, ctx.accel, s, ctx.seed);
    })};

// A large plane z = 0 seen from above (support/test_scenes.h): every camera ray hits it, and its
// shading normal is +z, so every pixel is (0.5, 0.5, 1) * scale.
Scene plane() { return testing::make_plane_under_sky(0.5f, 1.f, 8); }

void expect_every_pixel(const Image& img, const Rgb& expected) {
  ASSERT_EQ(img.size(), size_t(64));
  for (size_t i = 0; i < img.size(); ++i) {
    EXPECT_NEAR(img.pixels[i].r, expected.r, 1e-5f) << "pixel " << i;
    EXPECT_NEAR(img.pixels[i].g, expected.g, 1e-5f) << "pixel " << i;
    EXPECT_NEAR(img.pixels[i].b, expected.b, 1e-5f) << "pixel " << i;
  }
}

TEST(ToyIntegrator, IsListedByTheRegistry) {
  const std::vector<std::string> names = integrator_registry().names();
  EXPECT_NE(std::find(names.begin(), names.end(), "toy"), names.end()) << integrator_registry().joined_names();
  const IntegratorEntry& e = integrator_registry().at("toy");
  EXPECT_EQ(e.description, "shading normals as colours (a test of the registry)");
  ASSERT_EQ(e.schema.options.size(), 1u);
  EXPECT_EQ(e.schema.options[0].name, "toy-scale");
  EXPECT_EQ(e.schema.options[0].type, OptionType::real);
  EXPECT_EQ(e.schema.options[0].default_text, "1");
  EXPECT_TRUE(e.filter_names().empty());
  EXPECT_TRUE(e.composes_with(FilterChoice::kNone));
  EXPECT_FALSE(e.composes_with("hashed"));
}

TEST(ToyIntegrator, RendersThroughARenderSession) {
  ToySettings s;
  s.scale = 3.f;
  RenderSession session(plane(), make_render_config("toy", s, 1));
  EXPECT_EQ(session.run(RunLimit::for_passes(2)).passes, 2u);
  const RenderSnapshot snap = session.snapshot();
  expect_every_pixel(snap.mean, Rgb(1.5f, 1.5f, 3.f));
  EXPECT_EQ(snap.stats.integrator, "toy");
  EXPECT_EQ(snap.stats.spp, 2u);
  EXPECT_EQ(snap.stats.rays, 2u * 64u);
  EXPECT_EQ(snap.stats.details.number("toy.passes"), 2.0);
  // Its state is saved and restored like any other integrator's.
  RenderSession restored(plane(), make_render_config("toy", s, 1));
  restored.restore_state(session.save_state());
  EXPECT_EQ(restored.stats().details.number("toy.passes"), 2.0);
}

TEST(ToyIntegrator, RendersThroughConfigureRenderWithItsOption) {
  OptionValues given;
  given.set("toy-scale", "2");
  const RenderConfig config = configure_render("toy", "none", given);
  EXPECT_EQ(config.integrator, "toy");
  ASSERT_NE(std::any_cast<ToySettings>(&config.settings), nullptr);
  EXPECT_EQ(std::any_cast<ToySettings>(config.settings).scale, 2.f);
  const Scene scene = plane();
  const Accel accel(scene);
  expect_every_pixel(render(scene, accel, config, RunLimit::for_passes(1)).mean, Rgb(1.f, 1.f, 2.f));
  // Without the option: the struct's default scale 1.
  expect_every_pixel(render(scene, accel, configure_render("toy", "none", {}), RunLimit::for_passes(1)).mean,
                     Rgb(0.5f, 0.5f, 1.f));
}

TEST(ToyIntegrator, OptionsAreChecked) {
  OptionValues bad;
  bad.set("toy-scale", "-1");
  EXPECT_THROW(configure_render("toy", "none", bad), OptionError);
  // An option of another integrator names the integrator it belongs to.
  OptionValues other;
  other.set("pclt-alpha", "0.5");
  try {
    configure_render("toy", "none", other);
    ADD_FAILURE() << "no error";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("--pclt-alpha applies to --integrator pclt"), std::string::npos) << e.what();
  }
  // A filter it does not compose with.
  EXPECT_THROW(configure_render("toy", "hashed", {}), OptionError);
  // The wrong settings struct for it.
  const Scene scene = plane();
  EXPECT_THROW(RenderSession(scene, make_render_config("toy", 1.5f, 1)), Error);
}

}  // namespace
}  // namespace pathspace
