#include "theme.h"

#include <QApplication>
#include <QPalette>
#include <QStyle>
#include <QPainter>
#include <QProxyStyle>
#include <QStyleFactory>
#include <QStyleOption>
#include <QVariant>
#include <QWidget>

#include <cmath>

namespace jumo {

namespace {

Theme::Kind g_kind = Theme::Kind::System;
QPalette g_systemPalette;
bool g_systemKnown = false;
QString g_systemStyle;

enum class Set { Light, Dark, HighContrast };

Set colourSet()
{
    switch (g_kind) {
    case Theme::Kind::Light:
        return Set::Light;
    case Theme::Kind::Dark:
        return Set::Dark;
    case Theme::Kind::HighContrast:
        return Set::HighContrast;
    case Theme::Kind::System:
        break;
    }
    return Theme::isDark() ? Set::Dark : Set::Light;
}

QPalette darkPalette()
{
    QPalette p;
    const QColor window(45, 47, 50), base(30, 31, 34), text(230, 230, 230), disabled(130, 130, 130);
    p.setColor(QPalette::Window, window);
    p.setColor(QPalette::WindowText, text);
    p.setColor(QPalette::Base, base);
    p.setColor(QPalette::AlternateBase, QColor(40, 42, 45));
    p.setColor(QPalette::ToolTipBase, QColor(60, 62, 66));
    p.setColor(QPalette::ToolTipText, text);
    p.setColor(QPalette::PlaceholderText, QColor(150, 150, 150));
    p.setColor(QPalette::Text, text);
    p.setColor(QPalette::Button, QColor(55, 57, 61));
    p.setColor(QPalette::ButtonText, text);
    p.setColor(QPalette::BrightText, QColor(255, 120, 120));
    p.setColor(QPalette::Light, QColor(75, 77, 81));
    p.setColor(QPalette::Midlight, QColor(62, 64, 68));
    p.setColor(QPalette::Mid, QColor(100, 100, 105));
    p.setColor(QPalette::Dark, QColor(25, 25, 28));
    p.setColor(QPalette::Shadow, QColor(10, 10, 10));
    p.setColor(QPalette::Highlight, QColor(0x24, 0x68, 0xb4));   // white on it: 5.7:1
    p.setColor(QPalette::HighlightedText, Qt::white);
    p.setColor(QPalette::Link, QColor(110, 170, 240));
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, disabled);
    return p;
}

// Fusion outlines a check box in the window colour made darker: on a dark Base the box
// that is not checked all but vanishes, on a light one it is faint (1.65:1). In the light
// and dark themes it gets an edge of its own, 3:1 or more against the window.
class IndicatorEdgeStyle : public QProxyStyle
{
public:
    using QProxyStyle::QProxyStyle;

    void drawPrimitive(PrimitiveElement element, const QStyleOption *option, QPainter *painter,
                       const QWidget *widget) const override
    {
        QProxyStyle::drawPrimitive(element, option, painter, widget);
        if (element != PE_IndicatorCheckBox && element != PE_IndicatorItemViewItemCheck)
            return;
        painter->save();
        painter->setPen(Theme::isDark() ? QColor(150, 150, 150) : QColor(118, 118, 118));
        painter->setBrush(Qt::NoBrush);
        painter->drawRect(QRectF(option->rect).adjusted(0.5, 0.5, -1.5, -1.5));
        painter->restore();
    }
};

QPalette highContrastPalette()
{
    QPalette p;
    const QColor black(0, 0, 0), white(255, 255, 255), yellow(255, 255, 0);
    for (QPalette::ColorRole role : {QPalette::Window, QPalette::Base, QPalette::AlternateBase, QPalette::Button,
                                     QPalette::ToolTipBase, QPalette::Dark, QPalette::Shadow})
        p.setColor(role, black);
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText, QPalette::ToolTipText,
                                     QPalette::BrightText, QPalette::Light, QPalette::Midlight, QPalette::Mid})
        p.setColor(role, white);
    p.setColor(QPalette::PlaceholderText, QColor(200, 200, 200));
    p.setColor(QPalette::Highlight, yellow);
    p.setColor(QPalette::HighlightedText, black);
    p.setColor(QPalette::Link, yellow);
    for (QPalette::ColorRole role : {QPalette::WindowText, QPalette::Text, QPalette::ButtonText})
        p.setColor(QPalette::Disabled, role, QColor(170, 170, 170));
    // The edges Fusion draws from these (a combo box's arrow button) grey out too: a
    // disabled field must not keep the white edge of one that takes input.
    for (QPalette::ColorRole role : {QPalette::Light, QPalette::Midlight, QPalette::Mid})
        p.setColor(QPalette::Disabled, role, QColor(110, 110, 110));
    return p;
}

} // namespace

void Theme::apply(Kind kind)
{
    if (!g_systemKnown) {
        g_systemPalette = QApplication::palette();
        g_systemStyle = QApplication::style() ? QApplication::style()->name() : QString();
        g_systemKnown = true;
    }
    g_kind = kind;
    // Fusion draws field frames, check boxes and scroll-bar handles in a shade of the
    // window colour: black on black in high contrast. There they get white edges.
    qApp->setStyleSheet(kind == Kind::HighContrast
                                ? QStringLiteral(
                                          "QLineEdit, QAbstractSpinBox, QComboBox { border: 1px solid white; padding: 1px 3px; }"
                                          // A disabled field must not look like one to type in: a grey
                                          // dashed edge and grey text, as the palette's disabled text.
                                          "QLineEdit:disabled, QAbstractSpinBox:disabled, QComboBox:disabled"
                                          " { border: 1px dashed #aaaaaa; color: #aaaaaa; }"
                                          "QCheckBox::indicator, QAbstractItemView::indicator, QRadioButton::indicator"
                                          " { border: 1px solid white; background: black; width: 10px; height: 10px; }"
                                          "QCheckBox::indicator:checked, QAbstractItemView::indicator:checked"
                                          " { background: yellow; }"
                                          "QRadioButton::indicator { border-radius: 6px; }"
                                          "QRadioButton::indicator:checked { background: yellow; }"
                                          "QScrollBar::handle { background: white; }")
                                : QString());
    if (kind == Kind::System) {
        if (QStyle *style = QStyleFactory::create(g_systemStyle))
            QApplication::setStyle(style);
        QApplication::setPalette(g_systemPalette);
        return;
    }
    // Fusion draws every widget from the palette, so the palette is the whole theme.
    QStyle *fusion = QStyleFactory::create(QStringLiteral("Fusion"));
    QApplication::setStyle(kind == Kind::HighContrast ? fusion : new IndicatorEdgeStyle(fusion));
    switch (kind) {
    case Kind::Light: {
        QPalette light = QApplication::style()->standardPalette();
        // Fusion's own highlight takes white text at 3.7:1 only.
        light.setColor(QPalette::Highlight, QColor(0x1c, 0x64, 0xa8));
        light.setColor(QPalette::HighlightedText, Qt::white);
        QApplication::setPalette(light);
        break;
    }
    case Kind::Dark:
        QApplication::setPalette(darkPalette());
        break;
    case Kind::HighContrast:
        QApplication::setPalette(highContrastPalette());
        break;
    case Kind::System:
        break;
    }
}

Theme::Kind Theme::current()
{
    return g_kind;
}

bool Theme::isDark()
{
    switch (g_kind) {
    case Kind::Dark:
    case Kind::HighContrast:
        return true;
    case Kind::Light:
        return false;
    case Kind::System:
        break;
    }
    const QPalette p = g_systemKnown ? g_systemPalette : QApplication::palette();
    return p.color(QPalette::Window).lightness() < 128;
}

QColor Theme::color(Role role)
{
    const Set set = colourSet();
    // {light, dark, high contrast}
    auto pick = [set](QColor light, QColor dark, QColor high) {
        return set == Set::Light ? light : set == Set::Dark ? dark : high;
    };
    switch (role) {
    case Role::TileOk:
        return pick(QColor(0xe3, 0xf4, 0xe3), QColor(0x1f, 0x3d, 0x24), QColor(0x00, 0x00, 0x00));
    case Role::TileUncertain:
        return pick(QColor(0xff, 0xf3, 0xcf), QColor(0x4a, 0x40, 0x18), QColor(0x00, 0x00, 0x00));
    case Role::TileAlarm:
        return pick(QColor(0xff, 0xd8, 0xd8), QColor(0x5c, 0x1e, 0x1e), QColor(0x80, 0x00, 0x00));
    case Role::TileWarning:
        return pick(QColor(0xff, 0xe4, 0xb8), QColor(0x55, 0x3a, 0x10), QColor(0x00, 0x00, 0x00));
    case Role::BarFill:
        return pick(QColor(0x2f, 0x5f, 0x9e), QColor(0x7f, 0xb4, 0xec), QColor(0xff, 0xff, 0xff));
    case Role::BarTrack:
        return pick(QColor(0xff, 0xff, 0xff, 0xc0), QColor(0x00, 0x00, 0x00, 0x70), QColor(0x00, 0x00, 0x00));
    case Role::TileOffline:
        return pick(QColor(0xd9, 0xd9, 0xd9), QColor(0x3a, 0x3a, 0x3a), QColor(0x00, 0x00, 0x00));
    case Role::TileIdle:
        return pick(QColor(0xec, 0xec, 0xec), QColor(0x33, 0x35, 0x38), QColor(0x00, 0x00, 0x00));
    case Role::TileWrongDevice:
        return pick(QColor(0xff, 0xb0, 0xb0), QColor(0x6e, 0x1a, 0x1a), QColor(0x80, 0x00, 0x00));
    case Role::TileText:
        return pick(QColor(0x10, 0x10, 0x10), QColor(0xea, 0xea, 0xea), QColor(0xff, 0xff, 0xff));
    case Role::InfoBanner:
        return pick(QColor(0xff, 0xf3, 0xc0), QColor(0x4a, 0x40, 0x10), QColor(0xff, 0xff, 0x00));
    case Role::InfoBannerText:
        return pick(QColor(0x60, 0x40, 0x00), QColor(0xff, 0xec, 0xb0), QColor(0x00, 0x00, 0x00));
    case Role::ErrorBanner:
        return pick(QColor(0xff, 0xd0, 0xd0), QColor(0x5c, 0x1e, 0x1e), QColor(0x80, 0x00, 0x00));
    case Role::ErrorBannerText:
        return pick(QColor(0x60, 0x00, 0x00), QColor(0xff, 0xd6, 0xd6), QColor(0xff, 0xff, 0xff));
    case Role::NeutralBanner:
        return pick(QColor(0xec, 0xec, 0xec), QColor(0x3a, 0x3c, 0x40), QColor(0x00, 0x00, 0x00));
    case Role::NeutralBannerText:
        return pick(QColor(0x30, 0x30, 0x30), QColor(0xe0, 0xe0, 0xe0), QColor(0xff, 0xff, 0xff));
    case Role::Pending:
        return pick(QColor(0x80, 0x60, 0x00), QColor(0xf0, 0xc8, 0x50), QColor(0xff, 0xff, 0x00));
    case Role::Confirmed:
        return pick(QColor(0x20, 0x70, 0x20), QColor(0x80, 0xd8, 0x80), QColor(0x00, 0xff, 0x00));
    case Role::Refused:
        return pick(QColor(0xb0, 0x00, 0x00), QColor(0xff, 0x90, 0x90), QColor(0xff, 0x60, 0x60));
    case Role::Unknown:
        return pick(QColor(0xa0, 0x48, 0x00), QColor(0xff, 0xb0, 0x60), QColor(0xff, 0xa0, 0x00));
    case Role::Hint:
        return pick(QColor(0x60, 0x60, 0x60), QColor(0xa8, 0xa8, 0xa8), QColor(0xd0, 0xd0, 0xd0));
    case Role::ErrorValue:
        return pick(QColor(0xaa, 0x00, 0x00), QColor(0xff, 0x80, 0x80), QColor(0xff, 0x60, 0x60));
    case Role::LedAlarm:
        return pick(QColor(220, 30, 30), QColor(240, 60, 60), QColor(255, 40, 40));
    case Role::LedWarning:
        return pick(QColor(240, 170, 0), QColor(250, 190, 30), QColor(255, 220, 0));
    case Role::LedStatus:
        return pick(QColor(40, 170, 60), QColor(60, 200, 80), QColor(0, 255, 0));
    }
    return {};
}

QString Theme::bannerStyle(Role background, Role text)
{
    return QStringLiteral("background: %1; color: %2; padding: 4px").arg(color(background).name(), color(text).name());
}

void Theme::colourText(QWidget *widget, Role role, const QString &extraCss)
{
    widget->setProperty("jumoThemeRole", int(role));
    widget->setProperty("jumoThemeCss", extraCss);
    widget->setStyleSheet(QStringLiteral("color: %1").arg(color(role).name())
                          + (extraCss.isEmpty() ? QString() : QStringLiteral("; ") + extraCss));
}

void Theme::plain(QWidget *widget)
{
    widget->setProperty("jumoThemeRole", QVariant());
    widget->setStyleSheet(QString());
}

void Theme::restyleWidgets()
{
    for (QWidget *widget : QApplication::allWidgets()) {
        const QVariant role = widget->property("jumoThemeRole");
        if (role.isValid())
            colourText(widget, Role(role.toInt()), widget->property("jumoThemeCss").toString());
    }
}

QString Theme::name(Kind kind)
{
    switch (kind) {
    case Kind::System:
        return QStringLiteral("system");
    case Kind::Light:
        return QStringLiteral("light");
    case Kind::Dark:
        return QStringLiteral("dark");
    case Kind::HighContrast:
        return QStringLiteral("high-contrast");
    }
    return {};
}

std::optional<Theme::Kind> Theme::fromName(const QString &name)
{
    // "Dark", " dark " and "high-contrast" or "HIGH-CONTRAST" all name a theme.
    for (Kind kind : kinds()) {
        if (Theme::name(kind).compare(name.trimmed(), Qt::CaseInsensitive) == 0)
            return kind;
    }
    return std::nullopt;
}

QString Theme::title(Kind kind)
{
    switch (kind) {
    case Kind::System:
        return tr("&System");
    case Kind::Light:
        return tr("&Light");
    case Kind::Dark:
        return tr("&Dark");
    case Kind::HighContrast:
        return tr("&High contrast");
    }
    return {};
}

QList<Theme::Kind> Theme::kinds()
{
    return {Kind::System, Kind::Light, Kind::Dark, Kind::HighContrast};
}

double Theme::contrast(const QColor &a, const QColor &b)
{
    auto luminance = [](const QColor &c) {
        auto channel = [](double v) { return v <= 0.03928 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); };
        return 0.2126 * channel(c.redF()) + 0.7152 * channel(c.greenF()) + 0.0722 * channel(c.blueF());
    };
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

} // namespace jumo
