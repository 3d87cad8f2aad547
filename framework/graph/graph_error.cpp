#include <shadelgraph/graph/graph_error.hpp>

#include <utility>

namespace sg::graph {
namespace {

std::string joinErrors(const std::vector<ValidationError>& errors) {
  std::string text = "render graph is invalid (" + std::to_string(errors.size()) + " error" +
                     (errors.size() == 1 ? "" : "s") + "):";
  for (const ValidationError& error : errors) text += "\n  " + error.what();
  return text;
}

}  // namespace

std::string ValidationError::what() const {
  std::string text;
  if (!pass.empty()) text += "pass '" + pass + "'";
  if (!resource.empty()) text += (text.empty() ? "" : ", ") + std::string("resource '") + resource + "'";
  if (!text.empty()) text += ": ";
  return text + message;
}

GraphError::GraphError(std::vector<ValidationError> errors)
    : std::runtime_error(joinErrors(errors)), errors_(std::move(errors)) {}

}  // namespace sg::graph
