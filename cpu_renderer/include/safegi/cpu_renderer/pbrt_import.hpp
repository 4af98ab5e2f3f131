// Reads a pbrt-v3 scene file (the subset docs/pbrt-import.md lists) into the
// renderer's Scene: tokenizer → parser → importer, in cpu_renderer/src/pbrt/.
//
// pbrt scenes carry no units: the caller says what one pbrt length unit is
// (`safegi-render scene.pbrt --length-unit cm`). Radiometric numbers are read
// in the unit system that keeps pbrt's pixel values: radiance L as W/(m² sr),
// intensity I as W/sr × (unit/m)² (docs/pbrt-import.md, "Units").
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "safegi/cpu_renderer/renderer.hpp"
#include "safegi/cpu_renderer/scene.hpp"
#include "safegi/cpu_renderer/scene_loader.hpp"

namespace safegi::render {

// A pbrt file that cannot be imported. what() is the whole diagnostic text in
// the compiler's style: "scene.pbrt:12:7: error: ...", the source line, a caret,
// an include chain and a help line where they apply; it ends with a newline.
class PbrtImportError : public SceneError {
 public:
  using SceneError::SceneError;
};

// Reads an included file or mesh; on failure returns nullopt and sets `error`.
using PbrtFileReader = std::function<std::optional<std::string>(const std::filesystem::path&, std::string& error)>;

struct PbrtImportOptions {
  double metres_per_unit = 0;  // what one pbrt length unit is, in metres (required, > 0)
  PbrtFileReader read_file;    // empty: read from disk
  // Image textures and environment maps (as SceneLoadOptions::read_image).
  // Empty: PFM files only (the core links no OpenImageIO); the programs pass read_image (image_io.hpp).
  ImageFileReader read_image;
};

struct PbrtScene {
  Scene scene;
  std::optional<CropWindow> crop;  // Film "cropwindow", in pixels
  std::string film_filename;       // Film "filename" (informative; the output name is the caller's)
  std::string warnings;            // rendered warnings (what pbrt-v3 would ignore too), empty if none
};

PbrtScene load_pbrt_scene(const std::filesystem::path& file, const PbrtImportOptions& options);

// `display_name` names the text in messages; Include and mesh paths resolve
// against `search_directory`, as pbrt-v3 resolves them against the main file's.
PbrtScene parse_pbrt_scene(std::string text, const std::string& display_name,
                           const std::filesystem::path& search_directory, const PbrtImportOptions& options);

// The metres in one `--length-unit` ("m", "cm", "mm", "in", "0.5 m", ...);
// throws SceneError naming the flag when it is not a positive length.
double parse_length_unit(const std::string& text);

// A scene file as the programs take it: pbrt-v3 by its `.pbrt` extension, its lengths in
// `length_unit` (which it needs: pbrt scenes carry no units), else the JSON format (which carries
// its units, so a `length_unit` is refused). The unit's misuse is a CommandLineError.
PbrtScene read_scene_file(const std::string& path, const std::string& length_unit, const ImageFileReader& read_image);

}  // namespace safegi::render
