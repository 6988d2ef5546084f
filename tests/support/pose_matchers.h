#pragma once
// Tolerance checks for positions and rotations, with messages that show both values.

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include <sstream>

namespace kumite::test {

class NearVector : public Catch::MatcherBase<Eigen::Vector3d> {
public:
    NearVector(Eigen::Vector3d expected, double tolerance) : m_expected(std::move(expected)), m_tolerance(tolerance) {}
    bool match(const Eigen::Vector3d& actual) const override { return (actual - m_expected).norm() <= m_tolerance; }
    std::string describe() const override {
        std::ostringstream out;
        out << "is within " << m_tolerance << " of [" << m_expected.transpose() << "]";
        return out.str();
    }

private:
    Eigen::Vector3d m_expected;
    double m_tolerance;
};
inline NearVector is_near(const Eigen::Vector3d& expected, double tolerance) { return {expected, tolerance}; }

// Same rotation (q and -q are equal) to within `tolerance_rad`.
class NearRotation : public Catch::MatcherBase<Eigen::Quaterniond> {
public:
    NearRotation(Eigen::Quaterniond expected, double tolerance_rad) : m_expected(expected), m_tolerance(tolerance_rad) {}
    bool match(const Eigen::Quaterniond& actual) const override {
        return actual.normalized().angularDistance(m_expected.normalized()) <= m_tolerance;
    }
    std::string describe() const override {
        std::ostringstream out;
        out << "is within " << m_tolerance << " rad of (w " << m_expected.w() << ", " << m_expected.vec().transpose() << ")";
        return out.str();
    }

private:
    Eigen::Quaterniond m_expected;
    double m_tolerance;
};
inline NearRotation is_near(const Eigen::Quaterniond& expected, double tolerance_rad) { return {expected, tolerance_rad}; }

} // namespace kumite::test

namespace Catch {
template <>
struct StringMaker<Eigen::Vector3d> {
    static std::string convert(const Eigen::Vector3d& v) {
        std::ostringstream out;
        out << "[" << v.transpose() << "]";
        return out.str();
    }
};
template <>
struct StringMaker<Eigen::Quaterniond> {
    static std::string convert(const Eigen::Quaterniond& q) {
        std::ostringstream out;
        out << "(w " << q.w() << ", " << q.vec().transpose() << ")";
        return out.str();
    }
};
} // namespace Catch
