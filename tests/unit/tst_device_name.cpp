// A device's one name (issue 53 point 16, capture/device_name.h): its serial number, else its
// family and bus address, else a label the user set, else its product; never the port or the
// tab it was opened in, which change per run. MCAP topics (McapRecording::channelsOf), the
// live bridge and session files take it; MATLAB's struct is "SN_<serial>" (the user guide).
#include "capture/capture_header.h"
#include "capture/device_name.h"
#include "capture/mcap_recording.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk;
using capture::CaptureHeader;

namespace {

CaptureHeader headerOf(const std::string &product, const std::string &serial, int busAddress = -1)
{
    model::DeviceIdentity id;
    id.productName = product;
    id.serial = serial;
    id.busAddress = busAddress;
    CaptureHeader h;
    h.setIdentity(id);
    h.set(CaptureHeader::kLinkKind, "HiPNUC serial");
    h.set(CaptureHeader::kPort, "/dev/pts/10");
    return h;
}

std::string topicName(const CaptureHeader &h)
{
    return capture::McapRecording::channelsOf(h).name;
}

} // namespace

class TstDeviceName : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void serialFirst()
    {
        const CaptureHeader h = headerOf("HI14R3", "0042", 1);
        QCOMPARE(topicName(h), std::string("0042"));
        QCOMPARE(capture::deviceName(h, "bench left"), std::string("0042"));
        QCOMPARE(capture::McapRecording::channelsOf(h).frameId, std::string("imu_0042"));
    }

    // Without a serial number: family and address, the same in every run.
    void familyAndAddress()
    {
        QCOMPARE(topicName(headerOf("HEC495", "", 2)), std::string("HEC495_addr2"));
        QCOMPARE(topicName(headerOf("HI14R3", "", 1)), std::string("HI14R3_addr1")); // a Modbus node
        CaptureHeader can = headerOf("HI14R3", "");
        can.set(CaptureHeader::kCanProtocol, "canopen");
        can.set(CaptureHeader::kCanNode, "5");
        QCOMPARE(topicName(can), std::string("canopen_node5"));
        can.set(CaptureHeader::kCanProtocol, "j1939");
        can.set(CaptureHeader::kCanNode, "8");
        QCOMPARE(topicName(can), std::string("j1939_node8"));
        // A bus address is kept in a capture's header and read back.
        QCOMPARE(headerOf("HEC495", "", 2).identity().busAddress, 2);
        QCOMPARE(headerOf("HI14R3", "").identity().busAddress, -1);
    }

    // A flash never written reads 0xFF: that is no serial number.
    void unwrittenSerialIsNone()
    {
        QCOMPARE(topicName(headerOf("HEC495", std::string(8, '\xff'), 3)), std::string("HEC495_addr3"));
        QCOMPARE(topicName(headerOf("HI14R3", "   ")), std::string("HI14R3"));
    }

    // Then the user's label, then the product; never the port.
    void labelThenProduct()
    {
        const CaptureHeader h = headerOf("HI14R3", "");
        QCOMPARE(capture::deviceName(h, "left wing"), std::string("left_wing"));
        QCOMPARE(capture::deviceName(h), std::string("HI14R3"));
        QCOMPARE(capture::deviceName(CaptureHeader{}), std::string("device"));
        QVERIFY(topicName(h).find("pts") == std::string::npos);
    }

    void matlabName()
    {
        QCOMPARE(capture::matlabDeviceName(headerOf("HI14R3", "0042")), std::string("SN_0042"));
        QCOMPARE(capture::matlabDeviceName(headerOf("HI14R3", "2181B60A6FDA63DF")), std::string("SN_2181B60A6FDA63DF"));
        QCOMPARE(capture::matlabDeviceName(headerOf("HI14R3", "SN-0042/a")), std::string("SN_0042_a"));
        QCOMPARE(capture::matlabDeviceName(headerOf("HEC495", "", 2)), std::string("HEC495_addr2"));
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstDeviceName)
#include "tst_device_name.moc"
