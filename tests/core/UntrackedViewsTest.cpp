// untracked() (core/UntrackedViews.hpp): copies for a kernel's captures that count no
// references, see the same memory, and leave Kokkos' tracking as they found it.
#include <gtest/gtest.h>

#include "argine/core/Types.hpp"
#include "argine/core/UntrackedViews.hpp"

namespace argine {
namespace {

struct TwoViews {
  Kokkos::View<Real*, MemSpace> a;
  Kokkos::View<int* [2], MemSpace> b;
};

bool trackingOn() {
  return Kokkos::Impl::SharedAllocationRecord<void, void>::tracking_enabled();
}

TEST(UntrackedViews, CopiesOfAStructCountNoReferencesAndSeeTheSameMemory) {
  TwoViews views{Kokkos::View<Real*, MemSpace>("a", 3), Kokkos::View<int* [2], MemSpace>("b", 2)};
  ASSERT_EQ(views.a.use_count(), 1);
  ASSERT_EQ(views.b.use_count(), 1);
  {
    const TwoViews copy = untracked(views);
    EXPECT_EQ(views.a.use_count(), 1);
    EXPECT_EQ(views.b.use_count(), 1);
    const TwoViews copy_of_copy = copy;  // a lambda's capture: still not counted
    EXPECT_EQ(views.a.use_count(), 1);
    const auto capture = [copy_of_copy](int i) { return copy_of_copy.a(i); };
    EXPECT_EQ(views.a.use_count(), 1);
    copy.a(1) = 2.5;
    copy_of_copy.b(1, 1) = 7;
    EXPECT_EQ(views.a(1), 2.5);
    EXPECT_EQ(views.b(1, 1), 7);
    EXPECT_EQ(capture(1), 2.5);
    EXPECT_EQ(copy.a.data(), views.a.data());
  }
  // their ends took nothing away
  EXPECT_EQ(views.a.use_count(), 1);
  EXPECT_EQ(views.b.use_count(), 1);
  // and an ordinary copy afterwards counts again: tracking is back on
  EXPECT_TRUE(trackingOn());
  const TwoViews counted = views;
  EXPECT_EQ(views.a.use_count(), 2);
  EXPECT_EQ(counted.b.use_count(), 2);
}

TEST(UntrackedViews, LeavesTrackingOffWhereTheCallerTurnedItOff) {
  Kokkos::View<Real*, MemSpace> view("v", 1);
  Kokkos::Impl::shared_allocation_tracking_disable();
  const auto copy = untracked(view);
  const bool on_inside = trackingOn();
  Kokkos::Impl::shared_allocation_tracking_enable();
  EXPECT_FALSE(on_inside);
  EXPECT_EQ(copy.data(), view.data());
  EXPECT_EQ(view.use_count(), 1);
}

}  // namespace
}  // namespace argine
