#include "discovery/can_survey.h"

#include "protocol/can/canopen.h"
#include "protocol/can/hec495_can.h"
#include "protocol/can/hipnuc_canopen_objects.h"
#include "protocol/can/j1939_config.h"
#include "protocol/can/sdo.h"

#include <utility>

namespace imudesk::discovery {

namespace can = protocol::can;
namespace co = protocol::can::canopen;
namespace j1939 = protocol::can::j1939;

namespace {

QString hex(uint32_t v)
{
    return QStringLiteral("0x%1").arg(v, 0, 16);
}

// J1939 RegVersion: major * 100 + minor * 10 + patch; CANopen 0x1018:3 (revision): major << 16 |
// minor << 8 | patch.
QString versionText(can::CanProtocol p, uint32_t v)
{
    if (p == can::CanProtocol::J1939)
        return QStringLiteral("%1.%2.%3").arg(v / 100).arg(v / 10 % 10).arg(v % 10);
    return QStringLiteral("%1.%2.%3").arg(v >> 16 & 0xFF).arg(v >> 8 & 0xFF).arg(v & 0xFF);
}

} // namespace

CanSurvey::CanSurvey(QString bus, uint8_t hostAddress) : m_bus(std::move(bus)), m_host(hostAddress) {}

CanSurvey::Node &CanSurvey::node(can::CanProtocol p, int n)
{
    Node &x = m_nodes[{int(p), n}];
    x.protocol = p;
    x.node = n;
    return x;
}

void CanSurvey::heard(const can::CanFrame &f)
{
    ++m_framesHeard;
    if (f.extended) {
        const can::DecodedFrame d = m_j1939.decode(f);
        if (d.kind == can::FrameKind::J1939Data && d.node >= 0) {
            ++node(can::CanProtocol::J1939, d.node).dataFrames;
            return;
        }
        const can::DecodedFrame h = m_hec495.decode(f);
        if (h.kind == can::FrameKind::Hec495Data) {
            ++node(can::CanProtocol::Hec495, -1).dataFrames; // the extended variant names no node
            return;
        }
        if (d.kind == can::FrameKind::Unknown)
            ++m_unknown;
        return;
    }
    if (const auto hb = co::parseHeartbeat(f)) {
        Node &n = node(can::CanProtocol::CanOpen, hb->node);
        if (hb->state == 0) { // boot-up
            if (++n.bootUps == 2)
                conflict(hb->node, tr("node %1 sent its boot-up message twice while the bus was only listened to: two "
                                      "devices started with that node ID")
                                       .arg(hb->node));
        }
        return;
    }
    // A HiPNUC TPDO and an HEC495 PDO share the 0x180.. identifiers; each decoder checks its own
    // lengths and contents.
    // A frame both take (an HEC495 PDO of a HiPNUC TPDO's length) tells neither apart: it
    // counts only for a node that sends nothing else.
    const can::DecodedFrame t = m_canopen.decode(f);
    const can::DecodedFrame h = m_hec495.decode(f);
    const bool tpdo = t.kind == can::FrameKind::TpdoData && t.node >= 0;
    const bool pdo = h.kind == can::FrameKind::Hec495Data && h.node >= 0;
    if (tpdo && pdo)
        ++node(can::CanProtocol::CanOpen, t.node).ambiguous;
    else if (tpdo)
        ++node(can::CanProtocol::CanOpen, t.node).dataFrames;
    else if (pdo)
        ++node(can::CanProtocol::Hec495, h.node).dataFrames;
    else if (t.kind == can::FrameKind::Unknown && h.kind == can::FrameKind::Unknown)
        ++m_unknown;
}

std::vector<CanSurvey::Question> CanSurvey::questions() const
{
    std::vector<Question> out;
    bool j1939Heard = false, anything = false;
    for (const auto &[key, n] : m_nodes) {
        anything = true;
        j1939Heard = j1939Heard || n.protocol == can::CanProtocol::J1939;
    }
    if (j1939Heard || !anything) {
        for (uint16_t reg : {uint16_t(j1939::RegVersion), uint16_t(j1939::RegBaud)}) {
            Question q;
            q.kind = Question::Kind::J1939Register;
            q.node = j1939::kBroadcast;
            q.index = reg;
            q.frame = j1939::encodeReg(j1939::readRequest(j1939::kBroadcast, m_host, reg));
            out.push_back(q);
        }
    }
    for (const auto &[key, n] : m_nodes) {
        if (n.protocol != can::CanProtocol::CanOpen || !co::isStandardNodeId(n.node))
            continue;
        if (m_nodes.count({int(can::CanProtocol::Hec495), n.node}) && n.dataFrames == 0)
            continue; // an HEC495's frames and heartbeat: its protocol has no reads

        const std::pair<uint16_t, uint8_t> objects[] = {
            {0x1018, 1}, {0x1018, 2}, {0x1018, 3}, {uint16_t(co::hipnuc::ObjBaud), 0}};
        for (const auto &[index, sub] : objects) {
            Question q;
            q.kind = Question::Kind::Sdo;
            q.node = n.node;
            q.index = index;
            q.sub = sub;
            q.frame = co::sdoRead(uint8_t(n.node), index, sub);
            out.push_back(q);
        }
    }
    return out;
}

void CanSurvey::answered(const Question &q, const can::CanFrame &f)
{
    if (q.kind == Question::Kind::J1939Register) {
        const auto reply = j1939::parseReg(f);
        const auto request = j1939::parseReg(q.frame);
        if (!reply || !request || !j1939::answers(*reply, *request))
            return;
        m_answers[reply->sa].push_back(Answer{reply->sa, reply->status == 0, reply->value});
        return;
    }
    const auto reply = co::parseSdo(f);
    const auto request = co::parseSdo(q.frame);
    if (!reply || !request || !co::sdoAnswers(*reply, *request))
        return;
    m_answers[reply->node].push_back(Answer{reply->node, reply->kind != co::SdoKind::Abort, reply->value});
}

void CanSurvey::closeQuestion(const Question &q)
{
    auto answers = std::exchange(m_answers, {});
    const can::CanProtocol p = q.kind == Question::Kind::Sdo ? can::CanProtocol::CanOpen : can::CanProtocol::J1939;
    const QString what = q.kind == Question::Kind::Sdo ? tr("SDO read of %1:%2").arg(hex(q.index)).arg(q.sub)
                                                       : tr("J1939 read of register %1").arg(hex(q.index));
    for (const auto &[n, list] : answers) {
        if (list.size() > 1) {
            QStringList values;
            for (const Answer &a : list)
                values << (a.ok ? hex(a.value) : tr("refused"));
            const bool differ = std::any_of(list.begin(), list.end(), [&](const Answer &a) {
                return a.ok != list.front().ok || a.value != list.front().value;
            });
            conflict(n,
                     (differ ? tr("%1 answers from node %2 to one %3, with different contents (%4)")
                             : tr("%1 answers from node %2 to one %3 (%4)"))
                         .arg(list.size())
                         .arg(n)
                         .arg(what, values.join(QStringLiteral(", "))),
                     differ);
        }
        const Answer &a = list.front();
        Node &x = node(p, n);
        if (!a.ok)
            continue;
        if (q.kind == Question::Kind::J1939Register) {
            if (q.index == j1939::RegVersion)
                x.version = a.value;
            else if (q.index == j1939::RegBaud)
                x.baudCode = a.value;
        } else if (q.index == 0x1018) {
            (q.sub == 1 ? x.vendor : q.sub == 2 ? x.product : x.version) = a.value;
        } else if (q.index == co::hipnuc::ObjBaud) {
            x.baudCode = a.value;
        }
    }
}

void CanSurvey::conflict(int n, const QString &evidence, bool strong)
{
    Evidence &e = m_conflicts[n];
    ++e.times;
    if (e.text.isEmpty() || (strong && !e.strong)) {
        e.text = evidence;
        e.strong = strong;
    }
}

void CanSurvey::collect(int bitrate, const QString &bitrateWhy, QList<FoundDevice> *devices,
                        QList<Conflict> *conflicts) const
{
    for (const auto &[key, n] : m_nodes) {
        const bool hec495There = n.protocol == can::CanProtocol::CanOpen
            && m_nodes.count({int(can::CanProtocol::Hec495), n.node});
        // An HEC495's frames that a HiPNUC TPDO would fit, and its heartbeat, are the compass's.
        if (hec495There && n.dataFrames == 0 && !n.version)
            continue;
        if (n.dataFrames == 0 && n.ambiguous == 0 && !n.version && !n.baudCode && n.bootUps == 0)
            continue; // a heartbeat alone of a node that answered nothing
        FoundDevice d;
        d.link = FoundDevice::Link::Can;
        d.port = m_bus;
        d.node = n.node;
        switch (n.protocol) {
        case can::CanProtocol::J1939:
            d.family = QStringLiteral("j1939");
            d.model = tr("HiPNUC module (J1939)");
            break;
        case can::CanProtocol::CanOpen:
            d.family = QStringLiteral("canopen");
            d.model = tr("HiPNUC module (CANopen)");
            break;
        case can::CanProtocol::Hec495:
            d.family = QStringLiteral("hec495-can");
            d.model = QStringLiteral("HEC495");
            break;
        case can::CanProtocol::Auto: continue;
        }
        if (n.version)
            d.firmware = versionText(n.protocol, *n.version);
        if (n.vendor && n.product && (*n.vendor || *n.product))
            d.note = tr("vendor %1, product code %2").arg(hex(*n.vendor), hex(*n.product));
        d.bitrate = bitrate;
        d.bitrateWhy = bitrateWhy;
        if (bitrate <= 0 && n.baudCode) {
            const int rate = n.protocol == can::CanProtocol::J1939 ? j1939::baudFromCode(*n.baudCode)
                                                                   : co::hipnuc::baudFromCode(*n.baudCode);
            if (rate > 0) {
                d.bitrate = rate;
                d.bitrateWhy = tr("the module's own bit-rate setting (the interface cannot measure one)");
            }
        }
        if (n.dataFrames == 0 && n.ambiguous == 0 && n.bootUps == 0)
            d.note = d.note.isEmpty() ? tr("sends no data; answered when asked") : d.note;
        devices->append(d);
    }
    for (const auto &[n, evidence] : m_conflicts) {
        Conflict c;
        c.port = m_bus;
        c.link = QStringLiteral("can");
        c.address = n;
        c.evidence = evidence.times > 1 ? tr("%1 (and %n more time(s) like it)", nullptr, evidence.times - 1).arg(evidence.text)
                                        : evidence.text;
        c.advice = tr("Power the devices one at a time and give each its own node ID (its CAN tab, Settings, node "
                      "ID; save and reset), then sweep again.");
        conflicts->append(c);
    }
}

} // namespace imudesk::discovery
