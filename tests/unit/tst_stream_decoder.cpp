// One decoder per family (core/decode): each family's decoder is found by the family a
// capture names and by nothing else; a capture of a family ImuDesk has no decoder for is
// refused by name and never decoded as another; each decoder's samples carry the family's
// clocks (a HiPNUC frame's device time, an HEC495 answer's request bracket, a CAN record's
// stamp less its time on the bus) the same when fed directly (the live plug-ins) and through
// a capture's chunks (replay, export).
#include "capture/capture_decoder.h"
#include "capture/capture_header.h"
#include "decode/can_stream_decoder.h"
#include "decode/hipnuc_stream_decoder.h"
#include "decode/witlink_stream_decoder.h"
#include "protocol/can/canopen.h"
#include "protocol/can/can_record.h"
#include "protocol/hipnuc/payloads.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/witlink/frame.h"
#include "protocol/witlink/reply.h"
#include "../common/synthetic_capture.h"
#include "../common/test_main.h"

#include <QTest>

#include <random>

using namespace imudesk;

namespace {

struct Collect : decode::Sink {
    std::vector<model::Sample> samples;
    std::vector<std::string> types;
    std::vector<std::string> families;
    std::vector<std::string> text;
    std::vector<decode::PayloadError> errors;
    void onSample(const model::Sample &s, const decode::Record &r) override
    {
        samples.push_back(s);
        types.emplace_back(r.type);
        families.emplace_back(r.family);
    }
    void onText(decode::TextKind, const std::string &t, int64_t) override { text.push_back(t); }
    void onPayloadError(const decode::PayloadError &e, int64_t) override { errors.push_back(e); }
};

capture::CaptureReader::Chunk chunk(capture::ChunkKind kind, int64_t ns, const std::vector<uint8_t> &bytes)
{
    capture::CaptureReader::Chunk c;
    c.kind = kind;
    c.monotonicNs = ns;
    c.data = bytes.data();
    c.size = bytes.size();
    return c;
}

// The i-th frame of a module at 100 Hz.
std::vector<uint8_t> hi91Frame(uint64_t i)
{
    std::mt19937 rng(7);
    protocol::hipnuc::Hi91 h = synthetic::hi91(i, rng, 100);
    return protocol::hipnuc::buildFrame(protocol::hipnuc::encode(h));
}

} // namespace

class TstStreamDecoder : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void everyFamilyHasItsDecoder_data()
    {
        QTest::addColumn<QString>("linkKind");
        QTest::addColumn<QString>("family");
        QTest::newRow("HiPNUC serial") << "HiPNUC serial" << "HiPNUC serial";
        QTest::newRow("HEC495 serial") << "HEC495 serial" << "HEC495 serial";
        QTest::newRow("CAN") << "CAN" << "CAN";
        QTest::newRow("none named (an early capture)") << "" << "HiPNUC serial";
    }
    void everyFamilyHasItsDecoder()
    {
        QFETCH(QString, linkKind);
        QFETCH(QString, family);
        const auto d = decode::decoderFor(linkKind.toStdString());
        QVERIFY(d);
        QCOMPARE(QString::fromLatin1(d->family()), family);
    }

    void aFamilyWithoutADecoderIsRefusedByName_data()
    {
        QTest::addColumn<QString>("linkKind");
        QTest::addColumn<QString>("says");
        QTest::newRow("unknown") << "Xsens MTi serial" << "\"Xsens MTi serial\" link, which this version";
        QTest::newRow("Modbus") << "HiPNUC Modbus" << "does not decode Modbus captures offline";
    }
    void aFamilyWithoutADecoderIsRefusedByName()
    {
        QFETCH(QString, linkKind);
        QFETCH(QString, says);
        QVERIFY(!decode::decoderFor(linkKind.toStdString()));
        capture::CaptureHeader h;
        h.set(capture::CaptureHeader::kLinkKind, linkKind.toStdString());
        capture::CaptureDecoder d;
        QVERIFY(!d.configure(h));
        QVERIFY2(d.error().contains(linkKind) && d.error().contains(says), qPrintable(d.error()));
        QVERIFY(d.family().empty());
        // Bytes that a HiPNUC decoder would take for a frame: nothing comes of them.
        Collect sink;
        const auto frame = hi91Frame(1000);
        for (int i = 0; i < 3; ++i)
            d.feedChunk(chunk(capture::ChunkReceived, 1'000'000'000 + i * 10'000'000, frame), sink);
        d.finish(sink);
        QVERIFY(sink.samples.empty());
        QCOMPARE(d.counters().bytesIn, 0u);
    }

    // A converted file names what it came from as its link kind and the family whose bytes it
    // holds apart: the family decides.
    void theFamilyKeyDecidesOverTheLinkKind()
    {
        capture::CaptureHeader h;
        h.set(capture::CaptureHeader::kLinkKind, "raw byte dump");
        h.set(capture::CaptureHeader::kFamily, "HiPNUC serial");
        capture::CaptureDecoder d;
        QVERIFY2(d.configure(h), qPrintable(d.error()));
        QCOMPARE(d.family(), std::string("HiPNUC serial"));
        h.set(capture::CaptureHeader::kFamily, "");
        QVERIFY(!d.configure(h));
        QVERIFY(d.error().contains(QLatin1String("raw byte dump")));
    }

    // The same bytes at the same times: the capture path gives the live decoder's samples,
    // device clock and all, with the packet as the record.
    void hipnucCaptureDecodesAsTheFamilysDecoder()
    {
        capture::CaptureHeader h;
        h.set(capture::CaptureHeader::kLinkKind, "HiPNUC serial");
        h.set(capture::CaptureHeader::kBaud, "921600");
        capture::CaptureDecoder viaCapture;
        QVERIFY(viaCapture.configure(h));
        decode::HipnucStreamDecoder live;
        live.setBaud(921600);
        Collect a, b;
        const int64_t t0 = 5'000'000'000;
        for (int i = 0; i < 400; ++i) {
            const auto frame = hi91Frame(uint64_t(i));
            const int64_t at = t0 + int64_t(i) * 10'000'000 + (i % 7) * 30'000; // jitter
            viaCapture.feedChunk(chunk(capture::ChunkReceived, at, frame), a);
            live.feed(frame.data(), frame.size(), at, b);
        }
        QCOMPARE(a.samples.size(), size_t(400));
        QCOMPARE(b.samples.size(), a.samples.size());
        for (size_t i = 0; i < a.samples.size(); ++i) {
            QCOMPARE(a.samples[i].hostTimeNs, b.samples[i].hostTimeNs);
            QCOMPARE(a.samples[i].commonTimeNs, b.samples[i].commonTimeNs);
            QCOMPARE(a.types[i], std::string("HI91"));
            QCOMPARE(a.families[i], std::string("HiPNUC serial"));
        }
        // The device clock took over: later samples have a common time near their device time.
        QVERIFY(a.samples.back().commonTimeNs != 0);
        QVERIFY(std::llabs(a.samples.back().commonTimeNs - a.samples.back().hostTimeNs) < 5'000'000);
        QCOMPARE(viaCapture.counters().framesByType.at("HI91"), 400u);
        QCOMPARE(viaCapture.counters().frames, live.counters().frames);
    }

    // An HEC495 answer is stamped with its request's bracket (the midpoint of question and
    // answer); output the module sends on its own keeps its arrival alone; a reply that is no
    // data closes the bracket.
    void hec495AnswersCarryTheirRequestsBracket()
    {
        capture::CaptureHeader h;
        h.set(capture::CaptureHeader::kLinkKind, "HEC495 serial");
        capture::CaptureDecoder d;
        QVERIFY(d.configure(h));
        Collect sink;
        const auto reply = protocol::witlink::encodeFrame(protocol::witlink::anglesReply(0, 1.5, -2.25, 123.5));
        const std::vector<uint8_t> request = protocol::witlink::encodeFrame(0, 0x04);
        d.feedChunk(chunk(capture::ChunkSent, 1'000'000'000, request), sink);
        d.feedChunk(chunk(capture::ChunkReceived, 1'020'000'000, reply), sink);  // answers
        d.feedChunk(chunk(capture::ChunkReceived, 1'520'000'000, reply), sink);  // on its own
        QCOMPARE(sink.samples.size(), size_t(2));
        QCOMPARE(sink.types[0], std::string("HEC495 angles"));
        QCOMPARE(sink.samples[0].hostTimeNs, int64_t(1'020'000'000));
        QCOMPARE(sink.samples[0].commonTimeNs, int64_t(1'010'000'000));
        QCOMPARE(sink.samples[0].commonUncertaintyNs, int64_t(10'000'000));
        QCOMPARE(sink.samples[1].commonTimeNs, int64_t(0));
        QCOMPARE(d.counters().framesByType.at("HEC495 angles"), 2u);
        // A damaged reply (a bad checksum) is counted, not decoded.
        auto bad = reply;
        bad.back() ^= 0x5A;
        d.feedChunk(chunk(capture::ChunkReceived, 1'600'000'000, bad), sink);
        d.finish(sink);
        QCOMPARE(sink.samples.size(), size_t(2));
        QCOMPARE(d.counters().crcErrors, 1u);
    }

    // CAN: the node the header names is followed, another node's data is not merged in; the
    // interface's stamp less the frame's time on the bus is the common time.
    void canFollowsTheNamedNode()
    {
        using namespace protocol::can;
        capture::CaptureHeader h;
        h.set(capture::CaptureHeader::kLinkKind, "CAN");
        h.set(capture::CaptureHeader::kCanProtocol, "CANopen");
        h.set(capture::CaptureHeader::kCanNode, "5");
        h.set(capture::CaptureHeader::kBaud, "500000");
        capture::CaptureDecoder d;
        QVERIFY2(d.configure(h), qPrintable(d.error()));
        model::Sample s;
        s.fields |= model::FieldAcc;
        s.acc = {0.1, 0.2, 9.8};
        const CanFrame mine = canopen::encodeTpdo(0, 5, s);
        const CanFrame other = canopen::encodeTpdo(0, 9, s);
        const QByteArray a = toRecord(mine, false, 2'000'000'000);
        const QByteArray b = toRecord(other, false, 2'001'000'000);
        const std::vector<uint8_t> bytes(a.begin(), a.end());
        const std::vector<uint8_t> otherBytes(b.begin(), b.end());
        Collect sink;
        d.feedChunk(chunk(capture::ChunkReceived, 2'000'500'000, otherBytes), sink);
        d.feedChunk(chunk(capture::ChunkReceived, 2'000'400'000, bytes), sink);
        QCOMPARE(sink.samples.size(), size_t(1));
        QCOMPARE(sink.families[0], std::string("CAN"));
        QCOMPARE(sink.samples[0].commonTimeNs, int64_t(2'000'000'000) - wireTimeNs(mine, 500000));
        QCOMPARE(d.counters().frames, 2u);
    }
};

IMUDESK_TEST_MAIN(TstStreamDecoder)
#include "tst_stream_decoder.moc"
