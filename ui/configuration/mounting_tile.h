#pragma once
// A small 3D picture of one URFR mounting: a body (a box, its front marked) with the
// module on it and the module's X (red), Y (green) and Z (blue) axes drawn where the code
// puts them (body: X right, Y forward, Z up). Painted with QPainter in an oblique view;
// clickable, with a checked state. Never smaller than readableSize(); the picture is scaled to
// the tile, the axes and their letters always inside it.
#include <QWidget>

namespace imudesk::ui {

class MountingTile : public QWidget {
    Q_OBJECT
public:
    explicit MountingTile(int code, QWidget *parent = nullptr);
    int code() const { return m_code; }
    void setChecked(bool checked);
    bool isChecked() const { return m_checked; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return readableSize(); }
    // The smallest tile whose picture and caption ("URFR 205") read at this font.
    QSize readableSize() const;

Q_SIGNALS:
    void clicked(int code);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;

private:
    int m_code;
    bool m_checked = false;
};

} // namespace imudesk::ui
