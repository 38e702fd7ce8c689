// The bounded sample store (core/device/sample_store.h): the ring, and the latest value of
// each field when frames carry different fields (what the values table shows).
#include "device/sample_store.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk;

namespace {
model::Sample sample(const char *source, uint32_t fields, double v)
{
    model::Sample s;
    s.source = source;
    s.fields = fields;
    s.acc = {v, v, v};
    s.roll = s.pitch = s.yaw = v;
    s.latitudeDeg = v;
    s.hostTimeNs = int64_t(v * 1000);
    return s;
}
} // namespace

class TstSampleStore : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void ringKeepsTheNewest()
    {
        device::SampleStore store(3);
        QVERIFY(!store.latest());
        QVERIFY(!store.latestPerField());
        for (int i = 1; i <= 5; ++i)
            store.append({sample("HI91", model::FieldAcc, i)});
        QCOMPARE(store.totalAppended(), uint64_t(5));
        QCOMPARE(store.size(), size_t(3));
        QCOMPARE(store.latest()->acc.x, 5.0);
        const auto tail = store.since(0);
        QCOMPARE(tail.size(), size_t(3));
        QCOMPARE(tail.front().acc.x, 3.0);
    }

    // An HEC495 sends angles-only frames (0x84) between full records (0x14); a HiPNUC module
    // NMEA sentences between binary frames: each quantity keeps its latest value.
    void latestPerFieldKeepsEachQuantity()
    {
        device::SampleStore store;
        store.append({sample("HEC495 0x14", model::FieldAcc | model::FieldEuler, 1),
                      sample("HEC495 0x84", model::FieldEuler, 2)});
        const auto latest = store.latest();
        QVERIFY(!latest->has(model::FieldAcc)); // the newest frame alone has no acceleration
        auto v = store.latestPerField();
        QVERIFY(v->has(model::FieldAcc) && v->has(model::FieldEuler));
        QCOMPARE(v->acc.x, 1.0); // from the full record
        QCOMPARE(v->roll, 2.0);  // from the newer angles frame
        QCOMPARE(v->source, std::string("HEC495 0x84"));
        QCOMPARE(v->hostTimeNs, int64_t(2000));
        store.append({sample("GGA", model::FieldPosition, 3)});
        v = store.latestPerField();
        QCOMPARE(v->latitudeDeg, 3.0);
        QCOMPARE(v->roll, 2.0);
        store.clear();
        QVERIFY(!store.latestPerField());
        store.append({sample("HI91", model::FieldEuler, 4)});
        QVERIFY(!store.latestPerField()->has(model::FieldPosition)); // nothing left from before clear()
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSampleStore)
#include "tst_sample_store.moc"
