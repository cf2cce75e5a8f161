#pragma once
// Shared by the broadphase unit tests: one way to make each structure for typed tests, and the
// scalar of a structure.

#include <collide/broadphase.hpp>

#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

namespace collide::test {

/// make(tree_margin, cell): the structure S (the tree with that margin, the grid with that cell).
template <class S>
struct Make;
template <class T>
struct Make<broadphase::DynamicTree<T>> {
  static broadphase::DynamicTree<T> make(T margin, T) { return broadphase::DynamicTree<T>(margin); }
};
template <class T>
struct Make<broadphase::SweepAndPrune<T>> {
  static broadphase::SweepAndPrune<T> make(T, T) { return {}; }
};
template <class T>
struct Make<broadphase::UniformGrid<T>> {
  static broadphase::UniformGrid<T> make(T, T cell) { return broadphase::UniformGrid<T>(cell); }
};

/// The scalar type of a broadphase structure.
template <class S>
using ScalarOf = std::remove_cvref_t<decltype(std::declval<S>().box(broadphase::ProxyId{}).min().x())>;

/// The three structures in both scalars, for typed tests.
using BroadphaseStructures = ::testing::Types<broadphase::DynamicTree<float>, broadphase::SweepAndPrune<float>,
                                              broadphase::UniformGrid<float>, broadphase::DynamicTree<double>,
                                              broadphase::SweepAndPrune<double>, broadphase::UniformGrid<double>>;

}  // namespace collide::test
