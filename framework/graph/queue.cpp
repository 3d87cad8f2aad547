#include <shadelgraph/graph/queue.hpp>

namespace sg::graph {

PassKind defaultPassKind(QueueClass queue) {
  switch (queue) {
    case QueueClass::Graphics: return PassKind::Raster;
    case QueueClass::AsyncCompute: return PassKind::Compute;
    case QueueClass::Transfer: return PassKind::Transfer;
  }
  return PassKind::Raster;
}

std::string_view toString(QueueClass queue) {
  switch (queue) {
    case QueueClass::Graphics: return "Graphics";
    case QueueClass::AsyncCompute: return "AsyncCompute";
    case QueueClass::Transfer: return "Transfer";
  }
  return "?";
}

std::string_view toString(PassKind kind) {
  switch (kind) {
    case PassKind::Raster: return "Raster";
    case PassKind::Compute: return "Compute";
    case PassKind::Transfer: return "Transfer";
  }
  return "?";
}

std::string toString(QueueMask mask) {
  std::string out;
  for (uint32_t q = 0; q < kQueueClassCount; ++q) {
    const auto queue = static_cast<QueueClass>(q);
    if (!any(mask & toMask(queue))) continue;
    if (!out.empty()) out += '|';
    out += toString(queue);
  }
  return out.empty() ? "None" : out;
}

}  // namespace sg::graph
