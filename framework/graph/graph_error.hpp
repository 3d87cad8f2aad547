#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sg::graph {

// One problem found by validate(), naming the pass and resource involved
// (either may be empty when the problem is not about one).
struct ValidationError {
  std::string pass;
  std::string resource;
  std::string message;

  // "pass 'p', resource 'r': message"
  std::string what() const;
};

// Thrown by compile() when validation fails; carries every error.
class GraphError : public std::runtime_error {
 public:
  explicit GraphError(std::vector<ValidationError> errors);
  const std::vector<ValidationError>& errors() const { return errors_; }

 private:
  std::vector<ValidationError> errors_;
};

}  // namespace sg::graph
