#pragma once
// What one CAN bus shows, as a plain value class: the frames heard while only listening tell
// which nodes send (J1939 source addresses, HiPNUC CANopen TPDOs and heartbeats, HEC495 PDOs);
// then one question at a time is asked (a J1939 register read to the broadcast address, CANopen
// SDO reads of the identity object 0x1018 and the bit-rate object of each CANopen node heard)
// and every answer to it is counted. Two answers from one address to one question, or a
// boot-up twice, is a conflict, with what was seen. No HEC495 node is asked anything: its CAN
// protocol has writes only (a compass is known by its PDOs). Nothing asked writes a setting.
#include "discovery/discovery_result.h"
#include "protocol/can/can_decoder.h"
#include "protocol/can/can_frame.h"

#include <QCoreApplication>

#include <map>
#include <optional>
#include <set>
#include <vector>

namespace imudesk::discovery {

class CanSurvey {
    Q_DECLARE_TR_FUNCTIONS(CanSurvey)
public:
    struct Question {
        enum class Kind { J1939Register, Sdo };
        Kind kind = Kind::J1939Register;
        protocol::can::CanFrame frame;
        int node = -1;          // SDO: the node asked; J1939: 255 (everyone)
        uint16_t index = 0;     // J1939 register or SDO index
        uint8_t sub = 0;
    };
    struct Answer {
        int node = -1;
        bool ok = false;
        uint32_t value = 0;
    };

    // bus: PLUGIN:INTERFACE, for the result. hostAddress: the J1939 source address of ImuDesk.
    explicit CanSurvey(QString bus = {}, uint8_t hostAddress = 0x55);

    // A frame heard while listening (received, not sent).
    void heard(const protocol::can::CanFrame &f);
    // Data frames heard, and frames no protocol of ours knows.
    int framesHeard() const { return m_framesHeard; }
    int unknownFrames() const { return m_unknown; }

    // The questions to ask, given what was heard: J1939 reads to everyone when a J1939 node
    // was heard (or nothing at all was), SDO reads to each CANopen node heard.
    std::vector<Question> questions() const;
    // A frame that arrived while question q was the one asked.
    void answered(const Question &q, const protocol::can::CanFrame &f);
    // Call when a question's time is over: its answers are judged (two from one node: a conflict).
    void closeQuestion(const Question &q);

    // bitrate: the rate the bus was heard at without errors (0: the interface takes none, as
    // Qt's virtualcan; the modules' own bit-rate settings stand in, said so).
    void collect(int bitrate, const QString &bitrateWhy, QList<FoundDevice> *devices, QList<Conflict> *conflicts) const;

private:
    struct Node {
        protocol::can::CanProtocol protocol = protocol::can::CanProtocol::Auto;
        int node = -1;
        int dataFrames = 0;
        int ambiguous = 0; // frames an HEC495 PDO and a HiPNUC TPDO both fit
        int bootUps = 0;
        std::optional<uint32_t> version;  // J1939 RegVersion / CANopen 0x1018:3
        std::optional<uint32_t> vendor;   // 0x1018:1
        std::optional<uint32_t> product;  // 0x1018:2
        std::optional<uint32_t> baudCode; // J1939 RegBaud / CANopen 0x209A
    };
    Node &node(protocol::can::CanProtocol p, int n);
    // strong: the answers differ (two devices beyond doubt), preferred as the evidence shown.
    void conflict(int node, const QString &evidence, bool strong = false);

    QString m_bus;
    uint8_t m_host;
    std::map<std::pair<int, int>, Node> m_nodes; // (protocol, node)
    // Answers to the question now asked, by node: more than one from a node is a conflict.
    std::map<int, std::vector<Answer>> m_answers;
    struct Evidence {
        QString text;
        bool strong = false;
        int times = 0; // questions answered twice, boot-ups seen twice
    };
    std::map<int, Evidence> m_conflicts; // node -> what showed two devices there
    protocol::can::CanDecoder m_j1939{protocol::can::CanProtocol::J1939};
    protocol::can::CanDecoder m_canopen{protocol::can::CanProtocol::CanOpen};
    protocol::can::CanDecoder m_hec495{protocol::can::CanProtocol::Hec495};
    int m_framesHeard = 0;
    int m_unknown = 0;
};

} // namespace imudesk::discovery
