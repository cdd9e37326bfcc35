#include "compare_command.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "pathspace/film/image_metrics.h"
#include "pathspace/io/image_io.h"
#include "distinct_files.h"
#include "number_options.h"

namespace pathspace::cli {

CLI::App* add_compare_command(CLI::App& app, CompareOptions* o) {
  CLI::App* cmd = app.add_subcommand(
      "compare", "Error of an image against a reference (MSE, relMSE, block relMSE, blotched blocks, FLIP)");
  cmd->add_option("image", o->image, "Image to measure (.exr, .pfm, .png, .hdr)")->required();
  cmd->add_option("reference", o->reference, "Reference image")->required();
  cmd->add_option("--reference-variance", o->reference_variance,
                  "Variance-of-the-mean image of the reference: removes its noise from the error");
  cmd->add_option("--error-map", o->error_map, "Write the per-pixel relative squared error here");
  cmd->add_option("--block", o->block,
                  "Side in pixels of the blocks that block relMSE and the blotched-block share average over")
      ->check(checked_integer("block", 1, 1 << 20))
      ->capture_default_str();
  cmd->add_option("--flip-ppd", o->flip_ppd,
                  "Pixels per degree of visual angle for FLIP (67: 0.7 m from a 0.7 m wide 3840-pixel monitor)")
      ->check(checked_real("flip-ppd", 1, 1000))
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "Print JSON instead of text");
  return cmd;
}

int run_compare_command(const CompareOptions& o) {
  if (!o.error_map.empty()) {
    std::vector<NamedFile> inputs = {{"image", o.image}, {"reference", o.reference}};
    if (!o.reference_variance.empty()) inputs.push_back({"--reference-variance", o.reference_variance});
    check_distinct_files({{"--error-map", o.error_map}}, inputs);
  }
  const Image image = read_image(o.image);
  const Image reference = read_image(o.reference);
  Image variance;
  if (!o.reference_variance.empty()) variance = read_image(o.reference_variance);
  const ImageError e = image_error(image, reference, o.reference_variance.empty() ? nullptr : &variance);
  const BlockError b = block_error(image, reference, o.block);
  const double flip_mean = flip(image, reference, o.flip_ppd).mean;
  if (!o.error_map.empty()) write_image(o.error_map, rel_error_map(image, reference));
  if (o.json) {
    nlohmann::ordered_json j;
    j["image"] = o.image;
    j["reference"] = o.reference;
    j["mse"] = e.mse;
    j["rel_mse"] = e.rel_mse;
    j["mean_image"] = e.mean_image;
    j["mean_reference"] = e.mean_reference;
    j["block"] = o.block;
    j["block_rel_mse"] = b.block_rel_mse;
    j["blotched_share"] = b.blotched_share;
    j["flip"] = flip_mean;
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("MSE {:.6g}  relMSE {:.6g}  mean {:.6g} (reference {:.6g})\n", e.mse, e.rel_mse, e.mean_image,
               e.mean_reference);
    fmt::print("block {}x{}: relMSE {:.6g}  blotched {:.3g}% of {} blocks\n", o.block, o.block, b.block_rel_mse,
               100.0 * b.blotched_share, b.blocks);
    fmt::print("FLIP {:.6g} ({:g} pixels per degree)\n", flip_mean, o.flip_ppd);
  }
  return 0;
}

}  // namespace pathspace::cli
