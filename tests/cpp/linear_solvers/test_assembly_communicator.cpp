// SPDX-License-Identifier: BSD-3-Clause
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "tests/cpp/common/thread_communicator.h"

namespace mc {
namespace {

TEST(AssemblyCommunicator, AllGatherGivesEveryRankEveryRanksBytesInRankOrder) {
  // Lengths 0, 8 and 11 bytes: an empty message, whole words and a padded last word, with a NUL
  // inside (bytes, not C strings).
  const std::vector<std::string> sent{std::string(), std::string("8 bytes!"), std::string("eleven\0byte", 11)};
  test::ThreadRanks ranks(3);
  std::vector<std::vector<std::string>> received(sent.size());
  std::vector<std::thread> threads;
  for (int r = 0; r < 3; ++r)
    threads.emplace_back([&, r] {
      received[static_cast<std::size_t>(r)] =
          test::ThreadCommunicator(ranks, r).AllGather(sent[static_cast<std::size_t>(r)]);
    });
  for (std::thread& thread : threads) thread.join();
  for (const auto& on_rank : received) EXPECT_EQ(on_rank, sent);
}

}  // namespace
}  // namespace mc
