#pragma once
// Attitude maths after the HiPNUC manual's appendix 1 (quaternion / Euler / rotation
// matrix). Plain value types in the interface, Eigen inside.
//
// Quaternions are Quat{w, x, y, z} = [q0, q1, q2, q3], body -> navigation (Q_b2n):
// a vector given in body axes is rotated into navigation axes, v_n = C_b2n * v_b.
// q and -q are the same rotation; functions that return a quaternion return it
// normalised with w >= 0 unless noted.
//
// Frames
//   ENU (the devices' default and the wire format):
//     navigation x = East, y = North, z = Up;
//     body       x = right, y = forward, z = up (the module's printed axes, lying flat).
//   NED (aviation style):
//     navigation x = North, y = East, z = Down;
//     body       x = forward, y = right, z = down (FRD).
//   Both pairs are right-handed. The same physical attitude has a body->ENU quaternion
//   q_enu and a body(FRD)->NED quaternion q_ned; enuToNed()/nedToEnu() convert. The
//   axis swap between the two frames (N,E,D) = (y,x,-z) and (F,R,D) = (y,x,-z) is the
//   same matrix M (a 180 deg turn about (1,1,0)/sqrt2) for both frames, so
//   q_ned = m * q_enu * m^-1 with m = (0, 1/sqrt2, 1/sqrt2, 0); w is unchanged.
//
// Euler angles (degrees)
//   ENU 3-1-2: C_b2n = Rz(yaw) * Rx(pitch) * Ry(roll) (Z first, then X, then Y).
//     yaw   about Up, counter-clockwise seen from above positive, -180..180
//     pitch about body x (right), nose (body y) up positive, -90..90
//     roll  about body y (forward), right side down positive, -180..180
//   NED 3-2-1: C_b2n = Rz(yaw) * Ry(pitch) * Rx(roll) (Z first, then Y, then X).
//     yaw   about Down, clockwise seen from above positive, -180..180
//     pitch about body y (right), nose (body x) up positive, -90..90
//     roll  about body x (forward), right side down positive, -180..180
//   Both sequences turn about (vertical, right, forward), so for one physical attitude
//   roll_ned == roll_enu, pitch_ned == pitch_enu and yaw_ned == -yaw_enu (mod 360):
//   a pure 30 deg ENU yaw (nose turned 30 deg to the left of north) is NED yaw -30 deg
//   and heading 330 deg.
//   At gimbal lock (pitch = +-90 deg) roll and yaw are not separable and both atan2
//   arguments of the appendix formulas vanish; within about 0.0001 deg of lock the
//   functions return roll = 0 and put the whole turn into yaw, so the round trip still
//   gives the same rotation (and yaw_ned == -yaw_enu still holds).
//
// Heading: the compass bearing of the forward axis' horizontal projection, 0..360
// clockwise from north (0 = N, 90 = E). It equals -yaw_enu and yaw_ned (mod 360) and is
// undefined when the forward axis is vertical; headingDeg() then follows the gimbal-lock
// rule above (-yaw_enu with roll = 0: the bearing the nose would have if pitched back to
// level about the right axis; 0 for a pure +-90 deg pitch from north).
#include "mounting.h" // Matrix3: row-major 3x3, m[row][column]
#include "sample.h"

#include <array>

namespace imudesk::model {

struct Euler {
    double roll = 0, pitch = 0, yaw = 0; // deg
    friend bool operator==(const Euler &, const Euler &) = default;
};

// |q|; a valid attitude quaternion has norm 1.
double quatNorm(const Quat &q);
// True when all four parts are finite and the norm is not (close to) zero.
bool isUsableQuat(const Quat &q);
// q / |q| (sign kept); identity when q is not usable.
Quat normalized(const Quat &q);
// normalized(q) with w >= 0 (the other sign when w < 0): one representative per rotation.
Quat canonical(const Quat &q);
// Hamilton product a * b (apply b first, then a); conjugate = inverse for unit quaternions.
Quat multiply(const Quat &a, const Quat &b);
Quat conjugate(const Quat &q);
// Angle of the rotation between a and b in degrees (0..180); 0 for q and -q.
double angleBetweenDeg(const Quat &a, const Quat &b);
// v rotated by q (v_n = C_b2n * v_b); q is normalised first.
Vec3 rotate(const Quat &q, const Vec3 &v);

// The manual's direction cosine matrix C_b2n (q normalised first).
Matrix3 rotationMatrix(const Quat &q);

// Appendix 1, 10.36: ENU 3-1-2. q normalised first; pitch is clamped at +-90 deg.
Euler eulerEnu312(const Quat &q);
Quat quatFromEnu312(const Euler &e);

// Appendix 1, 10.37: NED 3-2-1 on a body(FRD) -> NED quaternion.
Euler eulerNed321(const Quat &qNed);
Quat quatFromNed321(const Euler &e);

// body(RFU) -> ENU  <->  body(FRD) -> NED, the same physical attitude (see above).
Quat enuToNed(const Quat &qEnu);
Quat nedToEnu(const Quat &qNed);

// body -> NWU (a module set to CONFIG IMU COORD 4)  <->  body -> ENU: the same body axes, the
// navigation frame turned 90 deg about up (N = ENU y, W = -ENU x).
Quat nwuToEnu(const Quat &qNwu);
Quat enuToNwu(const Quat &qEnu);

// Compass heading of the forward axis from a body -> ENU quaternion, 0 <= h < 360.
double headingDeg(const Quat &qEnu);

// A compass's heading (clockwise from north, any range) as a sample carries it: the heading
// itself (FieldHeading, 0..360, true or magnetic north) and, as for every other device, the
// world frame's yaw (ENU, counter-clockwise: -heading, wrapped to [-180, 180)). Sets no Euler
// flag: the caller does with pitch and roll.
void setCompassHeading(Sample &s, double headingCwDeg, bool trueNorth);

// Angle wrapped into [-180, 180) and [0, 360) degrees.
double wrap180(double deg);
double wrap360(double deg);

} // namespace imudesk::model
