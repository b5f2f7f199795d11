#include "apcs/scene/rigid_turn.h"

#include "apcs/geometry/bounding_box.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace apcs {

namespace {

Eigen::Vector3d to_eigen(const Vec3& v) { return {v.x, v.y, v.z}; }

Eigen::Vector3d centroid(std::span<const Vec3> points)
{
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const Vec3& point : points)
        sum += to_eigen(point);
    return sum / static_cast<double>(points.size());
}

// The turn of a drawing on one line: the covariance is singular(0)·to·fromᵀ, so `from` (KEY1's
// direction) and `to` (KEY2's) have the signs that match. All points at one place: no turn. A half
// turn has no smallest rotation: it is about the coordinate axis most across the line, x first
// (the thesis' face-on axis, so a line drawn face-on stays in its plane), then y, then z.
Eigen::Matrix3d line_turn(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double spread)
{
    if (spread == 0.0)
        return Eigen::Matrix3d::Identity();
    if (from.dot(to) > -1.0 + 1e-12)
        return Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix();
    const double least = from.cwiseAbs().minCoeff();
    Eigen::Index across = 0;
    while (std::abs(from(across)) > least + 1e-9)
        ++across;
    const Eigen::Vector3d axis = (Eigen::Vector3d::Unit(across) - from * from(across)).normalized();
    return Eigen::Matrix3d(Eigen::AngleAxisd(std::numbers::pi, axis));
}

// Kabsch: the rotation R minimising the sum of |R·(p − c1) − (q − c2)|².
Eigen::Matrix3d best_rotation(std::span<const Vec3> key1, std::span<const Vec3> key2, const Eigen::Vector3d& c1,
                              const Eigen::Vector3d& c2)
{
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < key1.size(); ++i)
        covariance += (to_eigen(key2[i]) - c2) * (to_eigen(key1[i]) - c1).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d& singular = svd.singularValues();
    // Points on one line leave the spin about that line free: SVD would pick any, and a part
    // would roll about its own length on the way. The smallest rotation between the lines instead.
    if (singular(1) <= 1e-12 * std::max(singular(0), 1e-300))
        return line_turn(svd.matrixV().col(0), svd.matrixU().col(0), singular(0));
    Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity();
    reflection(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
    return svd.matrixU() * reflection * svd.matrixV().transpose();
}

} // namespace

RigidTurn fit_rigid_turn(std::span<const Vec3> key1, std::span<const Vec3> key2)
{
    const Eigen::Vector3d c1 = centroid(key1);
    const Eigen::Vector3d c2 = centroid(key2);
    const Eigen::Matrix3d rotation = best_rotation(key1, key2, c1, c2);
    Eigen::Quaterniond quaternion(rotation);
    quaternion.normalize();
    if (quaternion.w() < 0)
        quaternion.coeffs() = -quaternion.coeffs();
    RigidTurn turn;
    turn.quaternion = {quaternion.w(), quaternion.x(), quaternion.y(), quaternion.z()};
    for (std::size_t i = 0; i < key1.size(); ++i) {
        const double deviation = (rotation * (to_eigen(key1[i]) - c1) + c2 - to_eigen(key2[i])).norm();
        if (deviation > turn.worst_deviation) {
            turn.worst_deviation = deviation;
            turn.worst_point = i;
        }
    }
    BoundingBox box;
    box.add(key1);
    turn.size = length(box.high() - box.low());
    return turn;
}

Affine partial_turn(const RigidTurn& turn, double fraction, const Vec3& centre)
{
    const auto& q = turn.quaternion;
    const Eigen::Quaterniond whole(q[0], q[1], q[2], q[3]);
    const Eigen::Matrix3d rotation = Eigen::Quaterniond::Identity().slerp(fraction, whole).toRotationMatrix();
    Affine about;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            about.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = rotation(i, j);
    about.t = centre - about(centre);
    return about;
}

} // namespace apcs
