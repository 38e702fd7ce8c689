#pragma once
// Tells which device family answers on a serial port, without user help: a HiPNUC module
// (binary 5A A5 frames, or an answer to "LOG VERSION") or a Witlink HEC495 compass (0x77
// frames: auto-output, or the answer to "read all" / "query address").
//
// At each baud: listen kListenMs for valid frames of either family (a streaming device);
// then send "LOG VERSION\r\n", the HEC495 "read all" to the given address and "query
// address" (to 00, which every HEC495 answers, 2.17), followed by "\r\n" so that a HiPNUC
// module discards the binary as an unknown line; then wait kAnswerMs for either answer
// (asked twice when nothing at all came back).
// Blocking (QSerialPort in the calling thread); call it from a worker or the CLI.
#include <QCoreApplication>
#include <QString>

#include <vector>

namespace imudesk::device {

class FamilyDetector {
    Q_DECLARE_TR_FUNCTIONS(FamilyDetector)

public:
    enum class Family { Unknown, Hipnuc, Hec495 };
    static constexpr int kListenMs = 120;
    static constexpr int kAnswerMs = 350;

    struct Result {
        Family family = Family::Unknown;
        int baud = 0;
        int address = -1; // HEC495: the module's address
        QString error;    // when nothing answered or the port failed
    };

    // HiPNUC's detection rates, then the HEC495's others (2400).
    static const std::vector<int> &defaultBauds();
    // bauds empty: defaultBauds(). hec495Address: where "read all" is sent.
    static Result detect(const QString &portName, const std::vector<int> &bauds = {}, int hec495Address = 0);
    static const char *familyName(Family f); // "hipnuc", "hec495", "unknown"
    // What a buffer of received bytes shows (exposed for tests).
    static Family classify(const QByteArray &bytes, int *hec495Address = nullptr);
};

} // namespace imudesk::device
