// shadelgraph view [scene] [render's frame options] [--script FILE] [--record DIR]:
// the interactive viewer (view/viewer.hpp).
#include "../commands.hpp"
#include "viewer.hpp"

namespace sg::app {

void addViewCommand(CLI::App& app) {
  static ViewArgs args;
  auto* cmd = app.add_subcommand("view", "Show a scene in a window: camera, panels, per-object modes (needs a display)");
  addViewOptions(*cmd, args);
  cmd->callback([] {
    int validation = 0;
    {
      view::Viewer viewer(args);
      viewer.run();
      viewer.close();
      validation = viewer.validationExitCode();
    }
    setExitCode(validation);
  });
}

}  // namespace sg::app
