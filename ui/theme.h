// The room the HMI runs in: light, dark or high-contrast colours, or the system's (the
// default: light or dark as the desktop's palette is). Widgets never hard-code a colour:
// they ask the theme for the colour of a meaning (a tile in alarm, a refused write), so
// every state stays readable in every theme. States are never told by colour alone:
// tiles and banners say them in words, LEDs differ in outline as well as fill.
#pragma once

#include <QColor>
#include <QCoreApplication>
#include <QString>

#include <optional>

class QWidget;

namespace jumo {

class Theme
{
    Q_DECLARE_TR_FUNCTIONS(jumo::Theme)

public:
    enum class Kind { System, Light, Dark, HighContrast };
    enum class Role {
        TileOk,            // online, alarms known, none active
        TileUncertain,     // alarms unknown or stale
        TileAlarm,         // an active alarm
        TileWarning,       // an active warning, no alarm
        TileOffline,       // not answering, line lost
        TileIdle,          // disconnected, identity being checked
        TileWrongDevice,   // another family at the address
        TileText,          // text on any tile colour
        BarFill, BarTrack, // a faceplate's bar: the value, and the scale it is against
        InfoBanner, InfoBannerText,        // read-only mode
        ErrorBanner, ErrorBannerText,      // wrong device, a log that loses records
        NeutralBanner, NeutralBannerText,  // identity being checked
        Pending, Confirmed, Refused, Unknown,   // write states, as text colours
        Hint,              // secondary text
        ErrorValue,        // an error value (overrange...) in a table
        LedAlarm, LedWarning, LedStatus,
    };

    // Applies a theme to the application (style and palette) and remembers it.
    static void apply(Kind kind);
    static Kind current();
    // The colours in use are the dark ones (Dark, or System on a dark desktop).
    static bool isDark();
    static QColor color(Role role);
    // "background: #rrggbb; color: #rrggbb" for a label in a banner role pair.
    static QString bannerStyle(Role background, Role text);

    static QString name(Kind kind);             // "system", "light", "dark", "high-contrast"
    static std::optional<Kind> fromName(const QString &name);
    static QString title(Kind kind);            // translated, for the menu
    static QList<Kind> kinds();

    // Colours a widget's text by meaning (extraCss: more declarations, "font-weight: bold");
    // restyleWidgets() colours it again when the theme changes. plain() takes it back.
    static void colourText(QWidget *widget, Role role, const QString &extraCss = QString());
    static void plain(QWidget *widget);
    static void restyleWidgets();

    // WCAG contrast ratio of two colours (1 to 21).
    static double contrast(const QColor &a, const QColor &b);
};

} // namespace jumo
