// dynanav render-map OUT/map.ply --out view.png: a picture of the dense static cloud (issue 15),
// from above or oblique, with the floor plane from OUT/map_info.json (written beside map.ply).
#include <spdlog/spdlog.h>

#include <opencv2/imgcodecs.hpp>

#include "apps/dynanav/commands.hpp"
#include "core/error.hpp"
#include "io/json_io.hpp"
#include "mapping/render_cloud.hpp"

namespace dynanav::cli {

void registerRenderMap(CLI::App& root, Action& chosen) {
  auto* sub = root.add_subcommand(
      "render-map", "render map.ply as an image (point splats, from above or oblique)");
  struct Args {
    std::string ply, out, view = "oblique";
    int width = 960, height = 720;
    double azimuth_deg = 0, elevation_deg = 50, max_height_m = 2.0;
  };
  auto args = std::make_shared<Args>();
  sub->add_option("MAP_PLY", args->ply, "map.ply written by dynanav run --map")->required();
  sub->add_option("--out", args->out, "output image (.png or .jpg)")->required();
  sub->add_option("--view", args->view, "top | oblique")->check(CLI::IsMember({"top", "oblique"}));
  sub->add_option("--width", args->width, "image width (px)");
  sub->add_option("--height", args->height, "image height (px)");
  sub->add_option("--azimuth", args->azimuth_deg,
                  "oblique: viewing direction about the vertical (deg)");
  sub->add_option("--elevation", args->elevation_deg, "oblique: how far the view looks down (deg)");
  sub->add_option("--max-height", args->max_height_m,
                  "leave out points higher above the floor (m; the ceiling)");
  sub->callback([&chosen, args] {
    chosen = [args] {
      const ColouredCloud cloud = readPly(args->ply);
      FloorPlane floor;
      const auto info_path = std::filesystem::path(args->ply).parent_path() / "map_info.json";
      if (std::filesystem::exists(info_path)) {
        const auto info = readJsonFile(info_path);
        if (info.contains("floor") && info["floor"].value("found", false)) {
          const auto& u = info["floor"]["up"];
          floor.found = true;
          floor.up = Vec3(u[0].get<double>(), u[1].get<double>(), u[2].get<double>());
          floor.offset_m = info["floor"]["offset_m"].get<double>();
        }
      }
      if (!floor.found)
        spdlog::warn("no floor plane in {}: world -y taken as up", info_path.string());
      CloudView view;
      view.kind = args->view;
      view.size = {args->width, args->height};
      view.azimuth_deg = args->azimuth_deg;
      view.elevation_deg = args->elevation_deg;
      view.max_height_m = args->max_height_m;
      const cv::Mat image = renderCloud(cloud, floor, view);
      std::vector<int> params;
      if (args->out.size() > 4 && args->out.substr(args->out.size() - 4) == ".jpg")
        params = {cv::IMWRITE_JPEG_QUALITY, 85};
      if (!cv::imwrite(args->out, image, params)) throw InputError(args->out, "cannot write image");
      spdlog::info("render-map: {} points -> {}", cloud.size(), args->out);
      return kExitOk;
    };
  });
}

}  // namespace dynanav::cli
