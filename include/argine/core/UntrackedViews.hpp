#pragma once
/// @file UntrackedViews.hpp
/// Copies of Views, or of structs of Views, for one kernel's captures without reference
/// counting.
///
/// Every copy of a counted View is an atomic increment, and its end a decrement, in a call
/// into the Kokkos library; a kernel whose lambda captures a copy of MaterialPoints (28
/// Views) or GridFields (14) makes two such copies. The shipped levee's step made about
/// 1,830 of them, 4 % of its time on 2,757 points (doc/scaling.md, "Fixed costs of the
/// step"). Kokkos copies a kernel's functor the same way (parallel_for turns tracking off
/// around it).

#include <Kokkos_Core.hpp>

namespace argine {

/// A copy of `views` (a View or a struct of Views) whose Views count no references, and
/// whose own copies (a lambda's captures) count none either. The caller's `views` must
/// outlive it and keep its allocations while it is used: for a kernel's captures within one
/// call, never for a member.
template <class Views>
Views untracked(const Views& views) {
  using Record = Kokkos::Impl::SharedAllocationRecord<void, void>;
  const bool tracking = Record::tracking_enabled();
  Kokkos::Impl::shared_allocation_tracking_disable();
  Views copy(views);
  if (tracking) Kokkos::Impl::shared_allocation_tracking_enable();
  return copy;
}

}  // namespace argine
