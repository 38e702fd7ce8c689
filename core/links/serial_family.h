#pragma once
// A device family that talks on a serial port, as the link opener sees it: how the detection
// recognises it and at which rates, the session it is opened with, and its simulator. The
// families are listed once, in serial_families.cpp; the detection (SerialFamilyScan) and the
// opener (LinkOpener) name none of them.
#include "device/device_link.h"
#include "io/transport.h"

#include <QByteArray>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

namespace imudesk::device {

struct LinkRequest;

// An opened link, not started yet, and what it needs (released after it). Connect to the
// link's signals first, then call start(): its state, identity and errors follow from the link.
struct OpenedLink {
    std::unique_ptr<DeviceLink> link;
    std::function<void()> start;
    std::shared_ptr<void> keepAlive;
};

// Watches what arrives at one rate for one family's frames or answers.
class SerialRecogniser {
public:
    virtual ~SerialRecogniser() = default;
    // `held` is all that arrived at this rate; the bytes from newFrom on are new (each byte is
    // looked at once, a frame cut between two calls is kept). True when they show the family;
    // *address then holds the device's bus address where it has one (else it is left alone).
    virtual bool recognise(const QByteArray &held, qsizetype newFrom, int *address) = 0;
};

class SerialFamilyKind {
public:
    virtual ~SerialFamilyKind() = default;
    // Stable name: LinkRequest::family and the CLI's JSON ("hipnuc", "hec495").
    virtual QString id() const = 0;
    // What a person calls it in messages ("a HiPNUC module"), translated.
    virtual QString displayName() const = 0;
    // The rates the detection tries for it, the likeliest first.
    virtual std::vector<int> bauds() const = 0;
    // What the detection sends at each rate for this family to answer; every family's query
    // goes out together, so none may upset another family's device. address: where a polled
    // device is asked (the request's deviceAddress).
    virtual QByteArray query(int address) const = 0;
    // A fresh recogniser for one rate.
    virtual std::unique_ptr<SerialRecogniser> recogniser() const = 0;
    // The family's session over transport, for r.address at r.baud (0: found by the session)
    // and r.deviceAddress, waiting for an unplugged device as r.autoReconnect says.
    virtual OpenedLink open(const LinkRequest &r, std::unique_ptr<io::Transport> transport) const = 0;
    // Starts the family's simulated device for a simulated request (its options in
    // r.simulator, else the defaults, moving as r.motion) and points r at it: address, baud,
    // deviceAddress, keepAlive. False, with why, when it cannot start.
    virtual bool startSimulator(LinkRequest &r, QString *error) const = 0;
};

// Every serial family, in detection order.
const std::vector<const SerialFamilyKind *> &serialFamilies();
// The family of that id; null when there is none.
const SerialFamilyKind *serialFamily(const QString &id);
// The rates the detection tries: each family's in order, each rate once.
const std::vector<int> &serialDetectionBauds();

} // namespace imudesk::device
