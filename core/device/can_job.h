#pragma once
// One configuration job of a CAN session: a sequence of steps, each a frame to send and what
// confirms it (a J1939 configuration reply, an SDO reply, an HEC495 write reply, traffic from
// a node, data frames starting or stopping, or nothing but a pause). A failed or timed-out step
// ends the job, except where silence is the confirmation (Nothing, NoPdoFrom).
#include "protocol/can/can_frame.h"

#include <QString>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace imudesk::device {

struct CanJob;

struct CanJobStep {
    enum class Expect {
        Nothing,       // send and go on after pauseMs
        J1939Reply,    // the configuration reply to tx (same address/cmd, status 0)
        SdoReply,      // 0x60 / 0x4x reply to tx; 0x80 = abort
        Hec495Reply,   // 0x60 reply with tx's index
        TrafficFrom,   // any frame from node `node` (the session followed a node change)
        PdoFrom,       // a data frame (TPDO, PDO, data PGN) from the target node (output on took effect)
        NoPdoFrom,     // no data frame from the target node until the timeout (output off took effect)
        PgnFrom,       // a J1939 data frame of PGN `pgn` from the target node (a trigger's answer)
        DataSeen,      // a data frame from the target ends the wait early; the timeout goes on too
    };
    bool hasTx = true;
    protocol::can::CanFrame tx;
    Expect expect = Expect::Nothing;
    int timeoutMs = 1000;
    int pauseMs = 0;
    int node = -1;                        // TrafficFrom
    uint32_t pgn = 0;                     // PgnFrom
    std::optional<uint32_t> expectValue;  // read-back must equal this
    int followNode = -1;                  // after this step the session follows this node
    QString what;                         // for messages: "read back PGN FF37 interval"
    // A step whose refusal or silence does not end the job: the job goes on without its value.
    bool optional = false;
    // Called when this step ends, before the next is sent, with its value (nullopt: an optional
    // step that was refused or not answered): may change the steps after `at` and the title
    // (the CANopen node-ID object chosen by the firmware version the module reports).
    std::function<void(std::optional<uint32_t> value, CanJob &job, size_t at)> adapt;
};

struct CanJob {
    quint64 id = 0;
    QString title;
    std::vector<CanJobStep> steps;
};

} // namespace imudesk::device
