#include <shadelgraph/scene/environment.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <stb_image.h>

#include <shadelgraph/scene/scene_error.hpp>

namespace sg::scene {

Environment loadEnvironment(const std::filesystem::path& file, float intensity) {
  if (!(std::isfinite(intensity) && intensity >= 0.0f))
    throw SceneError(file, "environment intensity must be a finite number >= 0");
  std::unique_ptr<FILE, int (*)(FILE*)> stream(std::fopen(file.c_str(), "rb"), std::fclose);
  if (!stream) throw SceneError(file, "cannot open the environment image");
  // stbi_loadf would also read a PNG or JPEG (and guess a gamma): only Radiance images carry radiance.
  if (!stbi_is_hdr_from_file(stream.get())) throw SceneError(file, "not a Radiance .hdr image (no #?RADIANCE header)");
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_file(stream.get(), &width, &height, &channels)) {
    const char* reason = stbi_failure_reason();
    throw SceneError(file, std::string("cannot read the Radiance header") + (reason ? std::string(": ") + reason : ""));
  }
  // Checked before decoding: a few bytes may claim any size.
  if (width < 2 || height < 1 || width > kMaxEnvironmentSide || height > kMaxEnvironmentSide)
    throw SceneError(file, "environment image is " + std::to_string(width) + "x" + std::to_string(height) +
                               ", expected 2 to " + std::to_string(kMaxEnvironmentSide) + " pixels on a side");
  std::unique_ptr<float, void (*)(void*)> pixels(stbi_loadf_from_file(stream.get(), &width, &height, &channels, 4),
                                                 stbi_image_free);
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    throw SceneError(file, std::string("cannot decode the Radiance image") + (reason ? std::string(": ") + reason : ""));
  }
  Environment env;
  env.file = file;
  env.width = uint32_t(width);
  env.height = uint32_t(height);
  env.intensity = intensity;
  env.rgba.assign(pixels.get(), pixels.get() + size_t(width) * size_t(height) * 4);
  for (float& v : env.rgba)
    if (!std::isfinite(v) || v < 0.0f) throw SceneError(file, "environment image has a negative or non-finite pixel");
  return env;
}

}  // namespace sg::scene
