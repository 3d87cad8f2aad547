#include "plan_queries.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sg::graph {
namespace {

using nlohmann::json;
using test::colorImage;
using test::extent;

// scene -> luminance (async) -> tonemap -> output, plus a culled debug pass.
RenderGraph exampleGraph() {
  RenderGraph g;
  auto hdr = g.createImage("hdr", ImageDesc{.format = Format::RGBA16F});
  auto lum = g.createBuffer("luminance", BufferDesc{.size = 256});
  auto debug = g.createImage("debug", colorImage());
  auto out = g.importImage("output", colorImage(), ImportedState{},
                           FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead});
  auto& scene = g.addPass("scene", QueueClass::Graphics);
  hdr = scene.write(hdr, Access::ColorAttachment);
  auto& avg = g.addPass("luminance", QueueClass::AsyncCompute);
  avg.read(hdr, Access::Sampled);
  lum = avg.write(lum, Access::StorageWrite);
  auto& view = g.addPass("debug-view", QueueClass::Graphics);
  view.read(hdr, Access::Sampled);
  (void)view.write(debug, Access::ColorAttachment);
  auto& tonemap = g.addPass("tonemap", QueueClass::Graphics);
  tonemap.read(hdr, Access::Sampled);
  tonemap.read(lum, Access::StorageRead);
  g.markOutput(tonemap.write(out, Access::ColorAttachment));
  return g;
}

TEST(GraphDump, JsonListsEveryPassAndResourceWithTheRequiredKeys) {
  const CompiledPlan plan = compile(exampleGraph(), extent());
  const json doc = json::parse(toJson(plan));

  ASSERT_EQ(doc.at("passes").size(), 4u);
  for (const json& pass : doc.at("passes")) {
    EXPECT_TRUE(pass.at("name").is_string());
    EXPECT_TRUE(pass.at("queue").is_string());
    EXPECT_TRUE(pass.at("culled").is_boolean());
    EXPECT_TRUE(pass.at("barriers").is_array());
    EXPECT_TRUE(pass.at("waits").is_array());
    ASSERT_FALSE(pass.at("accesses").empty());
    for (const json& access : pass.at("accesses")) {
      EXPECT_TRUE(access.at("resource").is_string());
      EXPECT_TRUE(access.at("access").is_string());
      EXPECT_TRUE(access.at("mode") == "read" || access.at("mode") == "write");
    }
  }
  const json& debugView = doc.at("passes").at(2);
  EXPECT_EQ(debugView.at("name"), "debug-view");
  EXPECT_EQ(debugView.at("culled"), true);
  EXPECT_EQ(doc.at("passes").at(1).at("queue"), "AsyncCompute");
  EXPECT_EQ(doc.at("passes").at(1).at("waits").at(0).at("queue"), "Graphics");
  EXPECT_EQ(doc.at("passes").at(0).at("barriers").at(0).at("resource"), "hdr");

  ASSERT_EQ(doc.at("resources").size(), 4u);
  for (const json& resource : doc.at("resources")) {
    EXPECT_TRUE(resource.at("kind").is_string());
    if (resource.at("kind") == "TransientImage" || resource.at("kind") == "TransientBuffer") {
      ASSERT_TRUE(resource.contains("memory"));
      if (resource.at("culled") == true) continue;
      EXPECT_TRUE(resource.at("memory").at("heap").is_number());
      EXPECT_TRUE(resource.at("memory").at("offset").is_number());
      EXPECT_TRUE(resource.at("memory").at("size").is_number());
    }
  }
  EXPECT_EQ(doc.at("resources").at(3).at("kind"), "Imported");
  EXPECT_EQ(doc.at("finalBarriers").size(), 1u);
  EXPECT_EQ(doc.at("batches").size(), 3u);
  EXPECT_TRUE(doc.at("memory").at("heapBytes").is_number());
}

TEST(GraphDump, DotColoursPassesByQueueAndDashesCulledOnes) {
  const std::string dot = toDot(compile(exampleGraph(), extent()));
  EXPECT_EQ(dot.rfind("digraph plan {", 0), 0u);
  EXPECT_NE(dot.find("label=\"luminance\""), std::string::npos);
  EXPECT_NE(dot.find("fillcolor=\"#fdae6b\", label=\"luminance\""), std::string::npos);  // async compute colour
  EXPECT_NE(dot.find("style=\"filled,dashed\", fillcolor=\"#9ecae1\", label=\"debug-view\""), std::string::npos);
  EXPECT_NE(dot.find("label=\"hdr v1\""), std::string::npos);
  EXPECT_EQ(dot.back(), '\n');
}

TEST(GraphDump, TextShowsOrderBatchesAndMemory) {
  const std::string text = toText(compile(exampleGraph(), extent()));
  EXPECT_NE(text.find("order: scene luminance tonemap"), std::string::npos) << text;
  EXPECT_NE(text.find("wait Graphics >= 1 at ComputeShader"), std::string::npos) << text;
  EXPECT_NE(text.find("debug-view (Graphics, Raster) culled"), std::string::npos) << text;
  EXPECT_NE(text.find("memory: "), std::string::npos) << text;
}

}  // namespace
}  // namespace sg::graph
