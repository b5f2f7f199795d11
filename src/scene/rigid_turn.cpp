#include "apcs/scene/rigid_turn.h"

#include "apcs/geometry/bounding_box.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>

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
    if (singular(1) <= 1e-12 * std::max(singular(0), 1e-300)) {
        const Eigen::Vector3d from = to_eigen(key1.back()) - to_eigen(key1.front());
        const Eigen::Vector3d to = to_eigen(key2.back()) - to_eigen(key2.front());
        if (from.norm() == 0.0 || to.norm() == 0.0)
            return Eigen::Matrix3d::Identity();
        return Eigen::Quaterniond::FromTwoVectors(from, to).toRotationMatrix();
    }
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
