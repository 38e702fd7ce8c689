#pragma once
// The Witlink HEC495 compass as a session-engine family (family_plugin.h), on RS-232 or RS-485.
//
// Link rules (manual "通讯协议"):
//   * Each request waits kReplyTimeoutMs for its reply and is sent up to kAttempts times:
//     an RS-485 module that is streaming may not hear a command (2.14). While the module
//     streams, a request is written right after an auto-output frame has arrived (the line
//     is quiet until the next one), or after kGapWaitMs without one.
//   * A reply answers the pending request when its command byte is one the request allows
//     (commands::expectedReplies) and it comes from the module's address (2.16's reply to
//     "set address" carries FF). The host's own request heard back (an RS-485 echo) is ignored;
//     where the manual's reply can equal the request byte for byte ("set content 00": 77 05 00
//     49 00 4E both ways), an identical frame that decodes as a valid reply is the reply, unless
//     the link has echoed before (then the first one of each attempt is the echo).
//   * After "set baud" succeeds the host follows to the new rate (the reply comes at the
//     old one, 2.13); after "set address" the new address is used; after "factory reset"
//     9600 and address 0.
//   * Opening: listen kListenMs; data frames mean the module streams (auto-output).
//     Otherwise ask "read all"; a module in its 3 s quiet window after power-on (2.14) still
//     answers commands, so identification retries until kIdentifyWindowMs has passed.
//   * In question/answer mode the family polls "read all" at the polling rate while no
//     other request is pending; auto-output frames (84 angles, 14 record) become samples.
//   * Output content NMEA 0183 (0x49 = 03): the module sends text sentences ($HCHDT) instead
//     of frames. Every line with a valid checksum is counted by its type; the ones
//     protocol::nmea decodes become samples (HDT: the heading), the others are handed out
//     raw (nmeaReceived). Text is not a data frame: polling goes on beside it, so pitch,
//     roll and the rest keep coming.
#include "clock/clock_model.h"
#include "device/baud_scan.h"
#include "device/family_plugin.h"
#include "device/hec495_result.h"
#include "model/sample.h"
#include "decode/witlink_stream_decoder.h"

#include <QElapsedTimer>
#include <QTimer>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace imudesk::device {

class Hec495Family : public FamilyPlugin, private decode::Sink, private decode::WitlinkStreamDecoder::FrameHook {
    Q_OBJECT
public:
    static constexpr int kReplyTimeoutMs = 300;
    static constexpr int kAttempts = 3;
    // "Collect a point" (0x67) is sent once: every one the module hears adds a point, so one
    // sent again because its reply was late would add two. It waits longer instead.
    static constexpr int kCollectTimeoutMs = 1000;
    static constexpr int kListenMs = 200;
    static constexpr int kIdentifyWindowMs = 3500;
    static constexpr int kLineIdleMs = 30;
    static constexpr int kGapWaitMs = 250;

    // What a request carries for the family (Request::command).
    struct Command {
        uint8_t command = 0;
        std::vector<uint8_t> data;
    };

    Hec495Family();
    static const std::vector<int> &detectionBauds();

    // Engine thread.
    void setAddress(int address) { m_address = address & 0xFF; }
    void setPollingRate(int hz);
    static Request makeRequest(uint8_t command, const QByteArray &data, int timeoutMs);

    QString linkKind() const override { return QStringLiteral("HEC495 serial"); }
    int firstBaud(int requestedBaud) const override;
    void opened(int requestedBaud) override;
    void stopping() override;
    void restartStream() override { m_decoder.restart(); }
    void resetCounters() override;
    void feed(const QByteArray &bytes, int64_t nowNs) override;
    bool midUnit() const override { return m_decoder.midUnit(); }
    void lineIdle(int64_t nowNs) override;
    void fillCounters(SessionStats &s) const override;
    void statsTick() override;
    QString prepare(Request &r) override;
    int holdWriteMs(const Request &) const override { return m_streaming ? kGapWaitMs : 0; }
    void unanswered(const Request &r, RequestResult &result) override;
    void finished(const Request &r, const RequestResult &result) override;

Q_SIGNALS:
    void baudChanged(int baud);
    void addressChanged(int address);
    // true: the module streams (auto-output); false: the family polls.
    void streamingChanged(bool streaming);
    // A calibration point was collected (automatic methods report them unasked).
    void calibrationPoint(int points);
    // An NMEA sentence with a valid checksum (output content NMEA 0183), without CR/LF.
    void nmeaReceived(const QString &sentence);

private:
    // What the family's decoder (decode/witlink_stream_decoder.h) gives: samples, NMEA text,
    // and each frame first, to match it to the request on the line.
    void onSample(const model::Sample &sample, const decode::Record &record) override;
    void onText(decode::TextKind kind, const std::string &text, int64_t hostNs) override;
    decode::WitlinkStreamDecoder::FrameVerdict frame(const protocol::witlink::Frame &f,
                                                     const protocol::witlink::Reply &r) override;
    void afterFrames();
    bool answersCurrent(const protocol::witlink::Frame &f) const;
    void followBaud(int baud);
    void poll();
    void setStreaming(bool on);
    void identified(int baud, const protocol::witlink::Reply *reply);

    decode::WitlinkStreamDecoder m_decoder; // the stream, its brackets and counters (also a replay's)
    std::vector<model::Sample> m_batch;
    bool m_unsolicitedData = false; // this read brought data frames no request asked for
    QTimer m_pollTimer{this};
    BaudScan m_scan{this}; // the identification: rates in turn
    protocol::witlink::Reply m_identifyReply;

    int m_address = 0;
    int m_pollHz = 10;
    bool m_streaming = false;
    bool m_identityKnown = false;
    bool m_linkEchoes = false;        // a request was heard back (RS-485 echo)
    std::pair<const Request *, int> m_echoHeard{}; // the attempt whose echo was skipped
    QElapsedTimer m_lastStreamFrame; // since the last auto-output frame

    uint8_t m_content = 0xFF;         // output content (0x49) last set, 0xFF: unknown
};

} // namespace imudesk::device

