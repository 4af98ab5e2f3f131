#include "safegi/runtime_vk/context.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "test_vk.hpp"

namespace safegi::vk {
namespace {

TEST(ContextTest, CreatesAHeadlessContextWithTheValidationLayer) {
  Context context;
  const ContextInfo& info = context.info();
  std::cout << "[ context  ] " << describe(info) << '\n';
  EXPECT_FALSE(info.device_name.empty());
  EXPECT_GE(VK_API_VERSION_MINOR(info.api_version), 2u);
  EXPECT_NE(info.validation, Validation::off);  // ctest sets SAFEGI_VK_VALIDATION
  ASSERT_FALSE(info.devices.empty());
  EXPECT_EQ(info.devices.at(info.device_index), info.device_name);
}

TEST(ContextTest, ChoosesADeviceByNameOrIndex) {
  std::string first;
  {
    Context by_index(ContextOptions{Validation::record, "0"});
    first = by_index.info().device_name;
    EXPECT_EQ(by_index.info().device_index, 0u);
  }
  Context by_name(ContextOptions{Validation::record, first.substr(0, 4)});
  EXPECT_EQ(by_name.info().device_name, first);
  EXPECT_TRUE(by_name.take_validation_messages().empty());
}

TEST(ContextTest, NamesTheDevicesWhenNoneMatches) {
  const std::string error = testing::error_of([] { Context context(ContextOptions{Validation::off, "no such gpu"}); });
  EXPECT_EQ(error.rfind("safegi::vk: no Vulkan device matching 'no such gpu' (SAFEGI_VK_DEVICE: an index or part of "
                        "a name); the devices are:\n  0: ",
                        0),
            0u)
      << error;
}

}  // namespace
}  // namespace safegi::vk
