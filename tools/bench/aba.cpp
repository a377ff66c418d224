// Pinocchio's aba timed in C++: the chain read from standard input as
// tools/bench/versus_pinocchio.py writes it, the fastest of 5 tries of the mean of
// `repeats` calls printed in µs on the first line, the q'' on the second.
//
// Input, whitespace-separated:
//   repeats  gx gy gz  joints
//   per joint: axis (0, 1, 2 for x, y, z)  parent (0 for the world)  px py pz
//              mass  cx cy cz  Ixx Ixy Iyy Ixz Iyz Izz  (about the mass centre)
//   nv values of q, then nv values of v
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/multibody.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>

int main() {
  using namespace pinocchio;
  long repeats;
  int joints;
  Eigen::Vector3d gravity;
  std::cin >> repeats >> gravity[0] >> gravity[1] >> gravity[2] >> joints;
  Model model;
  model.gravity.linear(gravity);
  for (int j = 0; j < joints; ++j) {
    int axis, parent;
    Eigen::Vector3d p, c;
    double mass, xx, xy, yy, xz, yz, zz;
    std::cin >> axis >> parent >> p[0] >> p[1] >> p[2] >> mass >> c[0] >> c[1] >> c[2] >>
        xx >> xy >> yy >> xz >> yz >> zz;
    SE3 placement(Eigen::Matrix3d::Identity(), p);
    JointIndex id;
    if (axis == 0) {
      id = model.addJoint(parent, JointModelRX(), placement, "j" + std::to_string(j));
    } else if (axis == 1) {
      id = model.addJoint(parent, JointModelRY(), placement, "j" + std::to_string(j));
    } else {
      id = model.addJoint(parent, JointModelRZ(), placement, "j" + std::to_string(j));
    }
    Eigen::Matrix3d inertia;
    inertia << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    model.appendBodyToJoint(id, Inertia(mass, c, inertia), SE3::Identity());
  }
  Data data(model);
  Eigen::VectorXd q(model.nq), v(model.nv), tau = Eigen::VectorXd::Zero(model.nv);
  for (int i = 0; i < model.nq; ++i) std::cin >> q[i];
  for (int i = 0; i < model.nv; ++i) std::cin >> v[i];
  double best = std::numeric_limits<double>::infinity();
  double sink = 0.0;
  for (int t = 0; t < 5; ++t) {
    auto start = std::chrono::steady_clock::now();
    for (long r = 0; r < repeats; ++r) {
      aba(model, data, q, v, tau);
      sink += data.ddq[0];
    }
    std::chrono::duration<double, std::micro> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count() / repeats);
  }
  std::printf("%.4f\n", best);
  const Eigen::VectorXd &ddq = aba(model, data, q, v, tau);
  for (int i = 0; i < model.nv; ++i) std::printf("%.17g ", ddq[i]);
  std::printf("\n");
  return sink == 12345.0;  // keeps the loop
}
