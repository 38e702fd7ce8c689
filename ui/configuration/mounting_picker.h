#pragma once
// URFR mounting picker (v1.7.1 §4.6.7.6): the 24 right-handed mountings as small 3D
// pictures with their descriptions; pick by picture, by code, or by where IMU X and IMU Y
// point on the body (IMU Z follows; X and Y at no right angle are refused). For firmware
// below 1.7.1 the command shown is the v1.6.6 nine-number matrix of the same mounting.
#include "settings/mounting_choice.h"

#include <QDialog>

#include <map>

class QComboBox;
class QLabel;
class QScrollArea;

namespace imudesk::ui {

class MountingTile;

class MountingPicker : public QDialog {
    Q_OBJECT
public:
    MountingPicker(int currentCode, bool legacyMatrix, QWidget *parent = nullptr);

    int code() const { return m_code; }
    bool setCode(int code);
    // False (and the reason shown) when X and Y are not at right angles.
    bool setDirections(settings::MountingChoice::Direction x, settings::MountingChoice::Direction y);
    // The value for the IMU.URFR setting ("205") and the command it sends on this firmware.
    QString value() const;
    QString commandText() const;
    QString errorText() const;
    MountingTile *tile(int code) const;
    QComboBox *codeBox() const { return m_codeBox; }
    QScrollArea *tileArea() const { return m_scroll; }

Q_SIGNALS:
    void codeChanged(int code);

private:
    void onDirectionsEdited();
    void refresh();

    int m_code;
    bool m_legacy;
    bool m_updating = false;
    std::map<int, MountingTile *> m_tiles;
    QComboBox *m_codeBox = nullptr;
    QComboBox *m_xBox = nullptr;
    QComboBox *m_yBox = nullptr;
    QLabel *m_zLabel = nullptr;
    QLabel *m_description = nullptr;
    QLabel *m_command = nullptr;
    QLabel *m_error = nullptr;
    QScrollArea *m_scroll = nullptr;
};

} // namespace imudesk::ui
