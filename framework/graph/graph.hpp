#pragma once

// Everything a plugin or executor uses: declaration, compile, the plan and its dumps.

#include <shadelgraph/graph/compile.hpp>
#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/graph_error.hpp>
#include <shadelgraph/graph/plan_dump.hpp>
#include <shadelgraph/graph/render_graph.hpp>
