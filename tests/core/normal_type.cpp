// Points and normals are different types where it matters (issue 15, pbrt's lesson): a point
// cannot be transformed as a normal, nor a normal as a point or direction; the right calls agree
// with the cofactor formula.
#include <catch2/catch.hpp>

#include <type_traits>
#include <utility>

#include <shadetool/core/affine.h>

using namespace shadetool;

namespace {

template <class N, class = void>
struct can_transform_normal : std::false_type {};
template <class N>
struct can_transform_normal<N, std::void_t<decltype(transform_normal(std::declval<Mat3d>(), std::declval<N>()))>>
    : std::true_type {};

template <class P, class = void>
struct can_transform_point : std::false_type {};
template <class P>
struct can_transform_point<P, std::void_t<decltype(transform_point(std::declval<Affine3d>(), std::declval<P>()))>>
    : std::true_type {};

template <class P, class = void>
struct can_transform_vector : std::false_type {};
template <class P>
struct can_transform_vector<P, std::void_t<decltype(transform_vector(std::declval<Affine3d>(), std::declval<P>()))>>
    : std::true_type {};

}  // namespace

static_assert(can_transform_normal<Normal3d>::value, "a normal transforms as a normal");
static_assert(!can_transform_normal<Vec3d>::value, "a point or direction does not transform as a normal");
static_assert(can_transform_point<Vec3d>::value && can_transform_vector<Vec3d>::value, "points and directions map by A");
static_assert(!can_transform_point<Normal3d>::value && !can_transform_vector<Normal3d>::value,
              "a normal never maps by A");
static_assert(sizeof(Normal3d) == sizeof(Vec3d), "no cost: the same three doubles");

TEST_CASE("A normal transformed by the signed cofactor stays perpendicular to mapped tangents", "[core][normal]") {
  Affine3d M;
  M.A = Mat3d{{{{2, 1, 0}, {0, -3, 1}, {1, 0, 0.5}}}};  // det = 2*(-1.5) - 1*(-1) + 0 = -2 < 0: a mirror
  const Vec3d t1{1, 0, -1}, t2{0, 1, 2};
  const Normal3d n(cross(t1, t2));
  const Normal3d m = transform_normal(signed_cofactor(M.A), n);
  CHECK(dot(m, transform_vector(M, t1)) == Approx(0).margin(1e-12));
  CHECK(dot(m, transform_vector(M, t2)) == Approx(0).margin(1e-12));
  // Outward stays outward under the mirror: the mapped normal points to the side the re-wound
  // face's cross product points to, i.e. against cross(A t1, A t2) when det A < 0.
  CHECK(determinant(M.A) < 0);
  CHECK(dot(m, cross(transform_vector(M, t1), transform_vector(M, t2))) < 0);
}
