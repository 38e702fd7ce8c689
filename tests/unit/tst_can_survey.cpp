// discovery::CanSurvey (issue 56): what a CAN bus shows while listened to, the questions asked
// from it, and the answers counted: frames built with the codecs as the modules send them.
#include "../common/test_main.h"
#include "discovery/can_survey.h"
#include "protocol/can/canopen.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"

#include <QTest>

using namespace imudesk;
using discovery::CanSurvey;
namespace can = protocol::can;
namespace co = protocol::can::canopen;
namespace j1939 = protocol::can::j1939;

class TestCanSurvey : public QObject {
    Q_OBJECT

    static model::Sample sample()
    {
        model::Sample s;
        s.acc = {0, 0, 1};
        return s;
    }

private Q_SLOTS:
    void listenAskAndCount()
    {
        CanSurvey survey(QStringLiteral("virtualcan:can0"));
        for (int i = 0; i < 5; ++i) {
            survey.heard(j1939::encodeData(j1939::PgnAcc, 12, sample()));
            survey.heard(co::encodeTpdo(0, 5, sample()));
        }
        QCOMPARE(survey.framesHeard(), 10);
        QCOMPARE(survey.unknownFrames(), 0);

        const auto questions = survey.questions();
        // Two J1939 reads to everyone (a J1939 node was heard), four SDO reads to node 5; none to 12.
        int j = 0, sdo = 0;
        for (const auto &q : questions) {
            if (q.kind == CanSurvey::Question::Kind::J1939Register) {
                ++j;
                QCOMPARE(q.node, 255);
                QVERIFY(q.frame.extended);
            } else {
                ++sdo;
                QCOMPARE(q.node, 5);
                QCOMPARE(q.frame.id, 0x605u);
                QCOMPARE(q.frame.data[0], uint8_t(0x40)); // an upload (read) request: nothing written
            }
        }
        QCOMPARE(j, 2);
        QCOMPARE(sdo, 4);

        for (const auto &q : questions) {
            if (q.kind == CanSurvey::Question::Kind::J1939Register) {
                // The J1939 module's answer from address 12 (version 1.7.1 -> 171; baud code 2 -> 500K).
                const uint32_t v = q.index == j1939::RegVersion ? 171 : 2;
                survey.answered(q, j1939::encodeReg(j1939::RegMessage{0x55, 12, q.index, j1939::CmdRead, 0, v}));
            } else if (q.index == 0x1018 && q.sub == 3) {
                // Two nodes at 5: two answers, different revisions.
                survey.answered(q, co::sdoReadReply(5, 0x1018, 3, 0x010701, 4));
                survey.answered(q, co::sdoReadReply(5, 0x1018, 3, 0x010606, 4));
            } else {
                survey.answered(q, co::sdoReadReply(5, q.index, q.sub, q.index == co::hipnuc::ObjBaud ? 2 : 0, 4));
                // An answer to another object is not an answer to this question.
                survey.answered(q, co::sdoReadReply(5, 0x2000, 0, 1, 4));
            }
            survey.closeQuestion(q);
        }
        QList<discovery::FoundDevice> devices;
        QList<discovery::Conflict> conflicts;
        survey.collect(0, QStringLiteral("no bit rate"), &devices, &conflicts);
        QCOMPARE(devices.size(), 2);
        for (const auto &d : devices) {
            QCOMPARE(d.bitrate, 500000); // the modules' own settings stand in
            QVERIFY(!d.bitrateWhy.isEmpty());
            if (d.node == 12) {
                QCOMPARE(d.family, QStringLiteral("j1939"));
                QCOMPARE(d.firmware, QStringLiteral("1.7.1"));
            } else {
                QCOMPARE(d.node, 5);
                QCOMPARE(d.family, QStringLiteral("canopen"));
                QCOMPARE(d.firmware, QStringLiteral("1.7.1")); // the first answer
            }
        }
        QCOMPARE(conflicts.size(), 1);
        QCOMPARE(conflicts.front().address, 5);
        QVERIFY2(conflicts.front().evidence.contains(QLatin1String("different contents (0x10701, 0x10606)")),
                 qPrintable(conflicts.front().evidence));
        QVERIFY(!conflicts.front().advice.isEmpty());
    }

    void bootUpTwiceIsAConflict()
    {
        CanSurvey survey;
        survey.heard(co::encodeHeartbeat(7, 0));
        survey.heard(co::encodeHeartbeat(7, 0x05));
        QList<discovery::FoundDevice> devices;
        QList<discovery::Conflict> conflicts;
        survey.collect(250000, {}, &devices, &conflicts);
        QVERIFY(conflicts.isEmpty()); // once is a node starting
        survey.heard(co::encodeHeartbeat(7, 0));
        devices.clear();
        survey.collect(250000, {}, &devices, &conflicts);
        QCOMPARE(conflicts.size(), 1);
        QCOMPARE(conflicts.front().address, 7);
        QCOMPARE(devices.size(), 1);
        QCOMPARE(devices.front().bitrate, 250000); // heard without errors at this rate
    }

    void aSilentBusIsAskedOnlyInJ1939()
    {
        // Nothing heard: the J1939 reads to everyone (a polled module answers); no SDO to anyone.
        const auto questions = CanSurvey().questions();
        QCOMPARE(questions.size(), size_t(2));
        QList<discovery::FoundDevice> devices;
        QList<discovery::Conflict> conflicts;
        CanSurvey().collect(500000, {}, &devices, &conflicts);
        QVERIFY(devices.isEmpty());
        QVERIFY(conflicts.isEmpty());
    }
};

IMUDESK_TEST_APPLESS_MAIN(TestCanSurvey)
#include "tst_can_survey.moc"
