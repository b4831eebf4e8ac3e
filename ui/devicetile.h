// A device's faceplate on the overview, laid out by kind from its map (FaceplateSpec): a
// power unit's values with bars against their nominal values or limits, a process
// controller's process value large with setpoint, output, mode and program. Its state
// (normal, warning, alarm, not answering, line lost...) reads at a glance three ways: a
// word, a shape and a colour, with a frame of its own; the active alarms are named.
// Clicking it, Enter or Space opens the device.
#pragma once

#include "bus/bus.h"
#include "protocol/registermap.h"
#include "theme.h"

#include <QTimer>
#include <QWidget>

namespace jumo {

class AlarmBitsModel;
class LiveValuesModel;
class RegisterMap;

class DeviceTile : public QWidget
{
    Q_OBJECT

public:
    enum class Density { Comfortable, Compact };
    // What the faceplate says about the device, worst first.
    enum class Summary { WrongDevice, LineLost, NotAnswering, Alarm, Warning, Uncertain, Normal, Checking, Disconnected };

    DeviceTile(DeviceId device, const RegisterMap &map, quint8 address, LiveValuesModel *values,
               AlarmBitsModel *alarms, QWidget *parent = nullptr);

    DeviceId device() const { return m_device; }
    void setCondition(const DeviceCondition &condition);
    void setDensity(Density density);
    Density density() const { return m_density; }

    // The faceplate's texts, as drawn (for tests and the tooltip). valuesText() has one
    // "Label: value" line per value, the primary value first.
    QString valuesText() const { return m_valuesText; }
    QString stateText() const { return m_stateText; }     // "Online", "Line lost since 10:42:17"
    QString alarmText() const { return m_alarmText; }     // "2 active alarm(s)", "Alarms unknown"
    QString alarmNames() const { return m_alarmNames; }   // "Load error, Max. alarm", "Load error (stale)"
    QString modeText() const { return m_modeText; }       // "Manual", "Mode unknown", empty without modes
    QString programText() const { return m_programText; }
    Summary summary() const { return m_summary; }
    QString summaryText() const { return summaryText(m_summary); }
    static QString summaryText(Summary summary);
    Theme::Role stateRole() const { return roleOf(m_summary); }
    static Theme::Role roleOf(Summary summary);
    // How many bars are drawn with a known scale (for tests).
    int barsDrawn() const { return m_barsDrawn; }
    // How many of them are filled: only a current value against a known scale is.
    int barsFilled() const { return m_barsFilled; }

    // "Online", "Not answering since 10:42:17": the words of the tile and the device list.
    static QString conditionText(const DeviceCondition &condition);
    // "2 active alarm(s)", "Alarms unknown", with "(stale)" where they are.
    static QString alarmsText(const DeviceCondition &condition, const AlarmBitsModel &alarms);
    // Takes the colours of the theme now in use.
    void restyle()
    {
        refresh();
        update();
    }

    // Larger on a screen with room to spare (the overview decides): text, shapes and
    // bars grow by this factor, 1 at their own size.
    void setScale(double scale);
    double scale() const { return m_scale; }

    QSize sizeHint() const override { return sizeHintFor(m_density, m_scale); }
    QSize sizeHintFor(Density density, double scale = 1) const;
    QSize minimumSizeHint() const override;

signals:
    void activated(jumo::DeviceId device);

protected:
    // On screen, the faceplate's entries and the scales of its bars are read sooner.
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    // The keyboard reaches each tile with Tab; Enter or Space opens the device.
    void keyPressEvent(QKeyEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Row
    {
        QString label;
        QString value;
        bool stale = false;
        bool errorValue = false;          // current, but an error value (overrange...)
        bool scaleKnown = false;
        std::optional<double> fraction;   // of the bar, for a current value against a known scale
        double zero = 0;                  // where the bar starts (0, or the middle of -100..100)
        bool beyond = false;              // the value is outside its scale
        QString scaleText;                // "of 100 A nominal"
    };

    void refresh();
    Row row(const QString &entryId, const QString &label) const;
    std::optional<double> number(const QString &entryId) const;
    std::optional<bool> stateOn(const QString &reference) const;
    // The first state that is on, "otherwise" when none, empty when one is unknown.
    std::optional<QString> firstOn(const QList<FaceplateState> &states, const QString &otherwise,
                                   bool *progress = nullptr) const;
    int lineHeight() const { return lineHeightFor(m_density, m_scale); }
    int lineHeightFor(Density density, double scale) const;
    QFont baseFont() const { return baseFontFor(m_scale); }
    QFont baseFontFor(double scale) const;
    QFont bigFont() const { return bigFontFor(m_density, m_scale); }
    QFont bigFontFor(Density density, double scale) const;
    void drawShape(QPainter &painter, const QRectF &box) const;

    DeviceId m_device;
    const RegisterMap &m_map;
    quint8 m_address;
    LiveValuesModel *m_values;
    AlarmBitsModel *m_alarms;
    static constexpr int refreshDelayMs = 100;
    QTimer m_pending;
    DeviceCondition m_condition;
    Density m_density = Density::Comfortable;
    double m_scale = 1;
    bool m_dirty = true;

    QString m_title;
    std::optional<Row> m_primary;
    QList<Row> m_rows;
    Summary m_summary = Summary::Disconnected;
    QString m_valuesText;
    QString m_stateText;
    QString m_alarmText;
    QString m_alarmNames;
    bool m_alarmNamesStale = false;
    QString m_modeText;
    QString m_programText;
    int m_barsDrawn = 0;
    int m_barsFilled = 0;
};

} // namespace jumo
