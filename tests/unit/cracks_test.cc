// SPDX-License-Identifier: LGPL-2.1-or-later
// Bond-cutting geometry: segments against 2D cracks and 3D crack triangles.
#include <pdfem/mesh/cracks.h>

#include <gtest/gtest.h>

using dealii::Point;
using pdfem::Mesh::Crack;

TEST(Cracks, SegmentCrossing2D)
{
  const Crack<2> crack{{{Point<2>(0., -1.), Point<2>(0., 1.)}}};
  EXPECT_TRUE(crack.cuts(Point<2>(-0.5, 0.), Point<2>(0.5, 0.2)));
  EXPECT_FALSE(crack.cuts(Point<2>(0.1, 0.), Point<2>(0.5, 0.2)));
  EXPECT_FALSE(
    crack.cuts(Point<2>(-0.5, 1.5), Point<2>(0.5, 1.5))); // beyond the tip
  EXPECT_TRUE(
    crack.cuts(Point<2>(0., 0.), Point<2>(0.5, 0.))); // touching counts
  EXPECT_TRUE(
    crack.cuts(Point<2>(-0.5, 1.), Point<2>(0.5, 1.))); // through the tip
  EXPECT_TRUE(
    crack.cuts(Point<2>(0., -0.5), Point<2>(0., 0.5))); // along the crack
  EXPECT_FALSE(
    crack.cuts(Point<2>(0., 1.5), Point<2>(0., 2.))); // collinear, apart
}

TEST(Cracks, SegmentCrossingTriangle3D)
{
  const Crack<3> crack{
    {{Point<3>(0., 0., 0.), Point<3>(0., 1., 0.), Point<3>(0., 0., 1.)}}};
  EXPECT_TRUE(crack.cuts(Point<3>(-1., 0.2, 0.2), Point<3>(1., 0.2, 0.2)));
  EXPECT_FALSE(
    crack.cuts(Point<3>(-1., 0.8, 0.8), Point<3>(1., 0.8, 0.8))); // outside
  EXPECT_FALSE(
    crack.cuts(Point<3>(0.1, 0.2, 0.2), Point<3>(1., 0.2, 0.2))); // one side
  EXPECT_TRUE(
    crack.cuts(Point<3>(-1., 0.5, 0.5), Point<3>(1., 0.5, 0.5))); // on an edge
  // Touching at the bounding boxes' faces (the boxes are tested first):
  // an end on the triangle, a segment through a vertex, one through the
  // vertex's corner of the box but beside the triangle.
  EXPECT_TRUE(crack.cuts(Point<3>(0., 0.2, 0.2), Point<3>(1., 0.2, 0.2)));
  EXPECT_TRUE(crack.cuts(Point<3>(-1., 1., 0.), Point<3>(1., 1., 0.)));
  EXPECT_TRUE(crack.cuts(Point<3>(-1., 0., 1.), Point<3>(1e-3, 0., 1.)));
  EXPECT_FALSE(crack.cuts(Point<3>(-1., 1., 1.), Point<3>(1., 1., 1.)));
  EXPECT_FALSE(
    crack.cuts(Point<3>(-1., 0.2, 1. + 1e-6), Point<3>(1., 0.2, 1. + 1e-6)));
}

TEST(Cracks, AnyOfSeveral)
{
  const std::vector<Crack<2>> cracks = {
    Crack<2>{{{Point<2>(0., 0.), Point<2>(0., 1.)}}},
    Crack<2>{{{Point<2>(2., 0.), Point<2>(2., 1.)}}}};
  EXPECT_TRUE(
    pdfem::Mesh::cut_by_any(cracks, Point<2>(1.5, 0.5), Point<2>(2.5, 0.5)));
  EXPECT_FALSE(
    pdfem::Mesh::cut_by_any(cracks, Point<2>(0.5, 0.5), Point<2>(1.5, 0.5)));
}
