// Sample CSV files (header row required; the mag_x, mag_y, mag_z columns in uT for
// `imudesk-cli magcal`): accepted forms, rejected forms with the line named, round trip.
#include "calib/sample_csv.h"
#include "../common/test_main.h"

#include <QTest>

using namespace imudesk::calib;

class TstSampleCsv : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void parse_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<int>("rows");
        QTest::addColumn<QString>("errorContains");
        QTest::newRow("plain") << QByteArray("mag_x,mag_y,mag_z\n1,2,3\n4,5,6\n") << true << 2 << "";
        QTest::newRow("CRLF, spaces, comments, blanks")
            << QByteArray("# capture\r\nmag_x, mag_y, mag_z\r\n\r\n 1.5 , -2e1 ,3\r\n# x\r\n4,5,6") << true << 2 << "";
        QTest::newRow("other columns, any order") << QByteArray("t,mag_z,acc_x,mag_y,mag_x\n0,3,9,2,1\n") << true << 1 << "";
        QTest::newRow("header only") << QByteArray("mag_x,mag_y,mag_z\n") << true << 0 << "";
        QTest::newRow("no header") << QByteArray("1,2,3\n4,5,6\n") << false << 0 << "header";
        QTest::newRow("empty") << QByteArray() << false << 0 << "empty";
        QTest::newRow("short row") << QByteArray("mag_x,mag_y,mag_z\n1,2\n") << false << 0 << "line 2";
        QTest::newRow("not a number") << QByteArray("mag_x,mag_y,mag_z\n1,2,3\n1,x,3\n") << false << 0 << "line 3";
        QTest::newRow("nan") << QByteArray("mag_x,mag_y,mag_z\n1,nan,3\n") << false << 0 << "mag_y";
        QTest::newRow("empty column name") << QByteArray("mag_x,,mag_z\n1,2,3\n") << false << 0 << "empty column";
        QTest::newRow("line too long") << (QByteArray("mag_x,mag_y,mag_z\n") + QByteArray(5000, '1')) << false << 0 << "longer";
        QByteArray wide;
        for (int i = 0; i < 70; ++i)
            wide += "c" + QByteArray::number(i) + ",";
        QTest::newRow("too many columns") << wide << false << 0 << "columns";
    }
    void parse()
    {
        QFETCH(QByteArray, text);
        QFETCH(bool, ok);
        QFETCH(int, rows);
        QFETCH(QString, errorContains);
        SampleTable t;
        QString error;
        QCOMPARE(SampleCsv::parse(text, t, &error), ok);
        if (ok) {
            QCOMPARE(int(t.rows.size()), rows);
            std::vector<Eigen::Vector3d> mag;
            QVERIFY(SampleCsv::magnetometer(t, mag, &error));
            QCOMPARE(int(mag.size()), rows);
            if (rows > 0 && t.columnIndex(QStringLiteral("t")) < 0)
                QCOMPARE(mag[0].x(), t.rows[0][0]);
        } else {
            QVERIFY2(error.contains(errorContains), qPrintable(error));
        }
    }

    void missingMagColumns()
    {
        SampleTable t;
        QVERIFY(SampleCsv::parse("acc_x,acc_y,acc_z\n1,2,3\n", t));
        std::vector<Eigen::Vector3d> mag;
        QString error;
        QVERIFY(!SampleCsv::magnetometer(t, mag, &error));
        QVERIFY(error.contains(QStringLiteral("mag_x")));
    }

    void roundTrip()
    {
        SampleTable t;
        t.columns = {QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
        t.rows = {{1.0 / 3, -2.5e-7, 1e300}, {0, -0.0, 42}};
        SampleTable back;
        QVERIFY(SampleCsv::parse(SampleCsv::write(t), back));
        QCOMPARE(back.columns, t.columns);
        QCOMPARE(back.rows, t.rows); // 17 significant digits: exact
    }
};

IMUDESK_TEST_GUILESS_MAIN(TstSampleCsv)
#include "tst_sample_csv.moc"
