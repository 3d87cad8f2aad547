#pragma once
// The forward frame's depth pre-pass choice (passes::ZPrepassChoice) as
// `render` prints it and writes it into --stats.
#include <memory>

#include <nlohmann/json.hpp>

#include <shadelgraph/render/renderer.hpp>
#include <z-prepass/z_prepass_choice.hpp>

namespace sg::app {

// The choice the forward package's z-prepass keeps, given to `renderer` before its first frame to read it back.
std::shared_ptr<passes::ZPrepassChoice> provideZPrepassChoice(render::Renderer& renderer);
// Null when no frame asked (e.g. the frame has no z-prepass pass).
nlohmann::json zPrepassJson(passes::ZPrepassChoice& choice);
void printZPrepass(passes::ZPrepassChoice& choice);

}  // namespace sg::app
