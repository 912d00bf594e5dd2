// The local store's pieces on their own: the cache keeps the balls most
// recently read within its budget, and the queue hands each waiting vertex
// out once, passing by those the cache holds or the caller took.
#include <gtest/gtest.h>

#include <memory>

#include "geodesics/ball_cache.hpp"
#include "geodesics/ball_queue.hpp"

namespace meshparticles::testing {
namespace {

std::shared_ptr<const Ball> ball_of_size(std::size_t entries) {
  Ball ball;
  ball.vertices.resize(entries);
  ball.distances.resize(entries);
  return std::make_shared<const Ball>(std::move(ball));
}

TEST(BallCache, EvictsTheLeastRecentlyReadToAQuarterUnderItsBudget) {
  const std::uint64_t ball_bytes = ball_of_size(10)->bytes();
  BallCache cache(5, 3 * ball_bytes);
  for (VertexId v = 0; v < 4; ++v) {
    cache.touch(v);
    cache.insert(v, ball_of_size(10));
  }
  cache.touch(0);  // read again: the last to go
  EXPECT_EQ(cache.evict_to_budget(), 2u);  // down to 2 balls, within three quarters of 3
  EXPECT_TRUE(cache.held(0));
  EXPECT_FALSE(cache.held(1));
  EXPECT_FALSE(cache.held(2));
  EXPECT_TRUE(cache.held(3));
  EXPECT_EQ(cache.peak_bytes(), 4 * ball_bytes);
  EXPECT_EQ(cache.evict_to_budget(), 0u);
}

TEST(BallCache, TheFirstBallKeptStays) {
  BallCache cache(2, 1000);
  const auto first = ball_of_size(1);
  cache.insert(1, first);
  cache.insert(1, ball_of_size(2));
  EXPECT_EQ(cache.held(1), first);
  EXPECT_EQ(cache.peak_bytes(), first->bytes());
}

TEST(BallQueue, HandsOutEachWaitingVertexOnceInOrder) {
  BallCache cache(6, 1000);
  BallQueue queue(6);
  for (const VertexId v : {4u, 1u, 3u, 5u}) queue.add(v);
  cache.insert(1, ball_of_size(1));  // solved meanwhile: passed by
  queue.claim(3);                    // the caller solves it: passed by
  const auto first = queue.take(cache);
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, 4u);
  EXPECT_TRUE(queue.being_solved(4));
  const auto second = queue.take(cache);
  ASSERT_TRUE(second);
  EXPECT_EQ(*second, 5u);
  EXPECT_TRUE(queue.idle(1));
  EXPECT_FALSE(queue.take(cache));
  const VertexId done[] = {4, 5, 3};
  queue.finish(done);
  for (const VertexId v : done) EXPECT_TRUE(queue.idle(v));
}

}  // namespace
}  // namespace meshparticles::testing
