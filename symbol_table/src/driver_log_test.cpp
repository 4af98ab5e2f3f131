#include "safegi/symbol_table/driver_log.hpp"

#include <gtest/gtest.h>

namespace safegi::gl {
namespace {

StageSymbols fragment_stage() {
  StageSymbols stage;
  stage.stage = Stage::fragment;
  stage.file = "shaders/direct.sgl.frag";
  stage.source_files = {"shaders/direct.sgl.frag", "shaders/lights.sgl.glsl"};
  return stage;
}

TEST(DriverLog, MapsMesaMessages) {
  EXPECT_EQ(map_driver_log("0:12(5): error: `x' undeclared\n0:13(1): warning: unused\n", fragment_stage()),
            "shaders/direct.sgl.frag:12:5: error: `x' undeclared\n"
            "shaders/direct.sgl.frag:13:1: warning: unused\n");
}

TEST(DriverLog, MapsSourceStringNumbersToIncludedFiles) {
  EXPECT_EQ(map_driver_log("1:4(9): error: syntax error", fragment_stage()),
            "shaders/lights.sgl.glsl:4:9: error: syntax error\n");
  EXPECT_EQ(map_driver_log("7:4(9): error: syntax error", fragment_stage()),
            "shaders/direct.sgl.frag:4:9: error: syntax error\n");
}

TEST(DriverLog, MapsNvidiaAndGenericMessages) {
  EXPECT_EQ(map_driver_log("0(21) : error C1008: undefined variable \"Lx\"", fragment_stage()),
            "shaders/direct.sgl.frag:21: error: undefined variable \"Lx\"\n");
  EXPECT_EQ(map_driver_log("ERROR: 0:3: 'Lx' : undeclared identifier\r\n", fragment_stage()),
            "shaders/direct.sgl.frag:3: error: 'Lx' : undeclared identifier\n");
}

TEST(DriverLog, KeepsUnknownLinesUnderTheStageFile) {
  EXPECT_EQ(map_driver_log("something odd\n\n", fragment_stage()), "shaders/direct.sgl.frag: something odd\n");
}

}  // namespace
}  // namespace safegi::gl
