#pragma once
// Register blocks to the Sample every other device family produces (core/model/sample.h):
// acc in G, gyr in deg/s, mag in uT, Euler angles in deg, quaternion w,x,y,z, pressure in Pa,
// temperature in degC, heave in m (heaveSurgeSway.x, as the HI92 path does).
// A field is filled only when all its registers are in the block.
#include "model/sample.h"
#include "register_block.h"

namespace imudesk::protocol::modbus {

class RegisterDecoder {
public:
    static constexpr const char *kHipnucSource = "MODBUS";
    static constexpr const char *kHec495Source = "HEC495";

    // HiPNUC sensor registers (0x34..0x4B, heave 0x4E/0x51).
    static model::Sample hipnucSample(const RegisterBlock &block);
    // HEC495 float angles from 0x0004: pitch -> pitch, roll -> roll, heading -> yaw (device convention).
    static model::Sample hec495Sample(const RegisterBlock &block);
    static model::Sample sample(DeviceKind kind, const RegisterBlock &block);
};

} // namespace imudesk::protocol::modbus
