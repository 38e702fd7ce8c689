#pragma once
// One decoder per family: how a family's stream (bytes, or CAN frame records) becomes samples,
// with their clocks, written once and used alike by the family's live plug-in
// (device/*_family.cpp) and by captures, replay and export (capture/capture_decoder.h).
//
// A decoder is fed what arrived, with its arrival on the host's monotonic clock, and tells a
// Sink, in the stream's order, what it decoded:
//   * samples, stamped: hostTimeNs is the arrival, commonTimeNs the family's clock model's
//     time (0 where it has none yet), each with the family's own record it came from;
//   * text: the lines between frames (a command's reply) and NMEA sentences;
//   * payload errors: a unit whose checksum held but whose content the manual cannot decode.
// Its counters are the stream's statistics (bytes, frames by type, errors), the same live and
// in a replay. A family's live plug-in adds what only a live link has (which request a reply
// answers) through the family's own hooks; the decoder holds no request queue.
//
// decoderFor(linkKind) looks a decoder up by the family the capture's header names (its link
// kind, "HiPNUC serial"); a family without one is refused by name (unsupportedWhy), never
// decoded as another family. Plain value classes, no Qt objects.
#include "model/sample.h"

#include <QString>

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace imudesk::decode {

// The family's own record behind a sample, for what writes the family's own layout (the
// vendor CSV of a HiPNUC packet). `native` points at the family's decoded unit for the
// duration of the call (a protocol::hipnuc::Packet for "HiPNUC serial"; null elsewhere).
struct Record {
    const char *family = "";  // the link kind of the decoder that made it
    std::string_view type;    // "HI91", "HEC495 record", "TPDO", "NMEA"
    int tag = 0;              // the family's numeric type where it has one (a HiPNUC packet tag)
    size_t unitBytes = 0;     // the bytes of the frame it came in (header and checksum included)
    const void *native = nullptr;
};

enum class TextKind {
    Line,          // a text line between frames (a command's reply, a banner)
    Nmea,          // an NMEA sentence (its sample given just before, when the decoder gives them)
    NmeaUndecoded, // with NMEA samples on: a sentence that gave no sample (shown raw)
};

struct PayloadError {
    std::string what;  // the manual's words for what could not be decoded
    int tag = -1;      // the unit's type byte, where the family has one
    size_t offset = 0; // where in the unit decoding stopped
};

class Sink {
public:
    virtual ~Sink() = default;
    virtual void onSample(const model::Sample &sample, const Record &record) = 0;
    virtual void onText(TextKind /*kind*/, const std::string & /*text*/, int64_t /*hostNs*/) {}
    virtual void onPayloadError(const PayloadError & /*error*/, int64_t /*hostNs*/) {}
};

// The stream's statistics, as the session's statistics show them.
struct Counters {
    uint64_t bytesIn = 0;
    uint64_t frames = 0;
    uint64_t crcErrors = 0;
    uint64_t lengthErrors = 0;
    uint64_t bytesSkipped = 0; // neither a frame, nor a reply line, nor an NMEA sentence
    uint64_t nmeaSentences = 0;
    uint64_t nmeaErrors = 0;
    uint64_t payloadErrors = 0; // units whose content could not be decoded (CAN: error frames)
    std::map<std::string, uint64_t> framesByType;
};

class StreamDecoder {
public:
    virtual ~StreamDecoder() = default;
    // The family's link kind ("HiPNUC serial"), as capture headers name it.
    virtual const char *family() const = 0;
    // What a capture's header says about its stream (the header's key-value pairs: the CAN
    // protocol and node). Also resets partial state and the clocks. The rate comes by setBaud.
    virtual void configure(const std::map<std::string, std::string> &header) = 0;
    // The line's rate (a frame's time on the wire).
    virtual void setBaud(int baud) = 0;
    virtual void feed(const uint8_t *data, size_t n, int64_t hostNs, Sink &sink) = 0;
    // A request went out at hostNs (families that stamp answers by their request).
    virtual void sent(int64_t /*hostNs*/) {}
    // Bytes are held for an unfinished unit.
    virtual bool midUnit() const = 0;
    // The line went quiet: release what an unfinished unit holds.
    virtual void lineIdle(int64_t hostNs, Sink &sink) = 0;
    // The end of the stream: release everything held.
    virtual void finish(int64_t hostNs, Sink &sink) = 0;
    // NMEA sentences' positions, fixes and times as samples too (Record::type "NMEA"): the live
    // session and the replay show them; exports and analyses take the sensors' samples alone.
    void setNmeaSamples(bool on) { m_nmeaSamples = on; }
    bool nmeaSamples() const { return m_nmeaSamples; }
    // Forget partial units (a new rate, a link opened again): the device's clocks carry on.
    virtual void restart() = 0;
    // Forget partial units and the clock models (a seek: what follows is not continuous).
    // Counters carry on.
    virtual void reset() = 0;
    virtual void resetCounters() = 0;
    virtual Counters counters() const = 0;

protected:
    // A sentence to the sink: its sample first when NMEA samples are on and it has one.
    void nmea(const std::string &sentence, int64_t hostNs, Sink &sink) const;

private:
    bool m_nmeaSamples = false;
};

// The decoder of a family by its link kind; null when ImuDesk has none (unsupportedWhy says
// why). An empty link kind is a capture written before headers named one: HiPNUC serial.
std::unique_ptr<StreamDecoder> decoderFor(const std::string &linkKind);
QString unsupportedWhy(const std::string &linkKind);
std::vector<std::string> decodedFamilies();
// The numeric type a sample's source has in its family, as Record::tag gives it beside the sample
// (a HiPNUC packet's tag: "HI91" -> 0x91); 0 when no family gives it one.
int recordTagOf(const std::string &source);

} // namespace imudesk::decode
