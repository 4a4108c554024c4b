// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <vector>

#include "custom_utilities/contact_state_cycle.h"

namespace mc {
namespace {

using States = std::vector<char>;

TEST(ContactStateCycle, ClosesOnAReturnToAnEarlierSetWithTheUnionSinceThen) {
  ContactStateCycle cycle(States{1, 0, 0});
  States a{1, 1, 0}, b{0, 1, 2}, again{1, 1, 0};
  EXPECT_EQ(cycle.Close(a), -1);
  EXPECT_EQ(cycle.Close(b), -1);
  EXPECT_EQ(cycle.Close(again), 1);     // the set of iteration 1
  EXPECT_EQ(again, (States{1, 1, 2}));  // {1,1,0} | {0,1,2} | {1,1,0}
  EXPECT_EQ(cycle.Last(), again);
}

TEST(ContactStateCycle, AnUnchangedSetIsNoCycle) {
  ContactStateCycle cycle(States{1, 0});
  States same{1, 0}, other{0, 0}, back{1, 0};
  EXPECT_EQ(cycle.Close(same), -1);
  EXPECT_EQ(cycle.Close(other), -1);
  EXPECT_EQ(cycle.Close(back), 0);  // back to the step's start
  EXPECT_EQ(back, (States{1, 0}));
}

}  // namespace
}  // namespace mc
