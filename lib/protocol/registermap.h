// The register map of one device family: every register the vendor manual lists,
// with its type and access, plus the family's protocol and timing facts.
#pragma once

#include <QHash>
#include <QList>
#include <QMap>
#include <QString>
#include <QVariantMap>

#include <algorithm>
#include <optional>

namespace jumo {

enum class ValueType { Float, Int16, UInt16, Int32, UInt32, Bool, Enum, Bitfield, Text };
enum class Access { Read, Write, ReadWrite };
enum class Storage { None, Ram, Eeprom };
enum class BitKind { Alarm, Warning, Status, Command };
// How urgently an entry is read, from what the map says about it: alarm words (bit fields
// with alarm or warning bits, the faceplate's mode and program words) every round, live
// values (measured values, outputs, states) as often as the line allows, settings
// (parameters, setpoints, identity, texts: values that change only by a write, a front
// panel or a program) at least every minute. Overridable per entry ("poll").
enum class PollClass { Alarm, Live, Setting };

// Byte order of a 32-bit value on the wire; the letters are the bytes of the
// big-endian value in the order they are sent (CDAB: low word at the lower address).
enum class WordOrder { ABCD, CDAB, BADC, DCBA };

// "0x00B1": the way addresses are written in the manuals, maps and CLI output.
QString formatAddress(quint16 address);

QString valueTypeName(ValueType type);
// A number with a unit and a range (not a bool, enum, bit field or text).
bool isNumeric(ValueType type);
std::optional<ValueType> valueTypeFromName(const QString &name);
QString accessName(Access access);
std::optional<Access> accessFromName(const QString &name);
QString storageName(Storage storage);
QString bitKindName(BitKind kind);
std::optional<BitKind> bitKindFromName(const QString &name);
QString wordOrderName(WordOrder order);
QString pollClassName(PollClass pollClass);
std::optional<PollClass> pollClassFromName(const QString &name);
// What an entry is while a view shows it: a setting is read as a live value, and live
// values a view shows are read ahead of the others at a target of their own (DevicePoll),
// never in the alarm words' place.
PollClass shownClass(PollClass pollClass);
// The number an enum text starts with ("100 A" -> 100), for nominal values kept as enums.
std::optional<double> leadingNumber(const QString &text);
std::optional<WordOrder> wordOrderFromName(const QString &name);
// "5.1.2 Operating level parameters" -> {5, 1, 2}: sections compare in the manual's order
// (5.2 before 5.10), whatever order their addresses put them in; a section without a
// number sorts after every numbered one.
QList<int> sectionNumber(const QString &group);
bool sectionBefore(const QString &a, const QString &b);

// How many digits a number is shown with: a fixed number of decimals (setpoints,
// percentages, temperatures), or significant digits (measured values over decades).
struct DisplayPrecision
{
    enum class Kind { Decimals, Significant };
    Kind kind = Kind::Decimals;
    int digits = 1;

    static DisplayPrecision decimals(int n) { return {Kind::Decimals, n}; }
    static DisplayPrecision significant(int n) { return {Kind::Significant, n}; }
    // The default for a float in this unit when its map names no precision.
    static DisplayPrecision defaultForUnit(const QString &unit);
    // "decimals:1", "significant:4": the map CSV's column.
    QString name() const;
    bool operator==(const DisplayPrecision &) const = default;
};

struct BitDefinition
{
    int bit = 0;
    int width = 1;
    QString id;
    QString label;
    BitKind kind = BitKind::Status;
    bool reserved = false;
    // Write-only words: where the device reports this bit's state ("entry.bit"), so a
    // write can keep it while other bits change.
    QString stateFrom;
    QString notes;
    QString erratum;

    quint16 mask() const { return quint16(((1u << width) - 1u) << bit); }
};

struct RegisterEntry
{
    quint16 address = 0;
    QString id;
    QString label;
    ValueType type = ValueType::UInt16;
    int textBytes = 0;      // text only: byte count including the NUL
    int reservedWords = 0;  // reserved blocks only: words spanned
    Access access = Access::Read;
    Storage storage = Storage::None;
    QString unit;
    // When the unit is set on the device (the process value's unit, what an alarm
    // monitors): the id of the map's configuredUnits text that says so; unit is empty.
    QString configuredUnit;
    // Floats only: the map's precision, or the default for the unit.
    DisplayPrecision precision;
    bool precisionFromMap = false;
    QString group;
    std::optional<double> minimum;
    std::optional<double> maximum;
    QMap<int, QString> enumValues;
    QList<BitDefinition> bits;
    std::optional<quint16> activationMask;
    // A write makes the device do something (start, cancel, change a segment): it is
    // sent once, never repeated, and cannot be verified by reading back.
    bool action = false;
    QString control;
    std::optional<double> restoreValue;
    // What the manual gives as the factory setting, or for a value the device keeps in
    // RAM as the value after power on; bools as 0 or 1, enums as their value.
    std::optional<double> defaultValue;
    QString precondition;
    bool reserved = false;
    QString alias;
    QString notes;
    QString erratum;
    // The map's own "poll", when it overrides what the entry's kind says.
    std::optional<PollClass> pollOverride;
    // What the scheduler reads it as: the override, or derived (RegisterMap::derivePollClass).
    PollClass pollClass = PollClass::Live;

    int wordCount() const;
    quint16 lastAddress() const { return quint16(address + wordCount() - 1); }
    bool isReadable() const { return access != Access::Write; }
    bool isWritable() const { return access != Access::Read; }
    bool isCommand() const;
    bool isAction() const { return action; }
    // A bit field with at least one alarm or warning bit that is not a reserve.
    bool hasAlarmBits() const;
    const BitDefinition *bitById(const QString &bitId) const;
};

enum class ProbeTest { TextContains, MaskNonZero, Answers, Exception };

struct IdentifyProbe
{
    quint16 address = 0;
    int words = 1;
    ProbeTest test = ProbeTest::Answers;
    QString text;            // TextContains
    quint16 mask = 0;        // MaskNonZero
    int exceptionCode = 0;   // Exception
};

struct ProtocolInfo
{
    QList<int> readFunctions;
    QList<int> writeFunctions;
    int maxReadWords = 0;
    int maxWriteWords = 0;
    WordOrder floatWordOrder = WordOrder::CDAB;
    WordOrder int32WordOrder = WordOrder::ABCD;
    QList<int> baudRates;
    QStringList dataFormats;
    int addressMin = 1;
    int addressMax = 247;
    std::optional<int> alwaysAnswersAddress;
    bool broadcast = true;
    double processingTimeMaxMs = 0;
    double turnaroundMs = 0;
    double minResponseTimeMaxMs = 0;
    std::optional<int> busErrorTimeoutMs;
    QString notes;

    // Whether a device of the family can be set to this baud rate and data format ("8E1").
    bool supports(int baudRate, const QString &dataFormat) const
    {
        return baudRates.contains(baudRate) && dataFormats.contains(dataFormat);
    }

    // What one request may really carry: the family's limit, capped by the Modbus RTU
    // frame (256 bytes: 125 words in a read reply, 123 in a 0x10 write), which is also
    // what QModbusRtuSerialClient accepts. IPC 300 and TYA 200 state 127 for both.
    int effectiveMaxReadWords() const { return std::min(maxReadWords, 125); }
    int effectiveMaxWriteWords() const { return std::min(maxWriteWords, 123); }
};

struct ErrorValueTexts
{
    QString underrange;
    QString overrange;
    QString invalid;
};

// How the device simulator animates a family: which entries its physical model drives
// (bindings by role), initial values, limit monitoring bits and command actions.
struct SimulationLimit
{
    QString value;          // entry id compared
    QString thresholdId;    // entry holding the threshold, or empty
    double threshold = 0;   // used when thresholdId is empty
    bool above = true;      // true: set while value > threshold; false: while below
    QStringList set;        // "entry.bit" or bool entry ids switched on while exceeded
};

struct SimulationSpec
{
    QString model;                          // "power_controller" or "process_controller"
    QHash<QString, QStringList> bindings;   // role -> entry ids (most roles have one)
    QVariantMap initial;                    // entry id -> number or text
    QList<SimulationLimit> limits;
    QHash<QString, QString> commands;       // "entry.bit" -> action
    QHash<QString, QString> status;         // "manual"/"tuning" -> "entry.bit"
    // Pairs of references that are one signal on the device (a bool register and the bit
    // that reports it): the simulator keeps them equal whichever is written.
    QList<QPair<QString, QString>> links;

    QString binding(const QString &role) const { return bindings.value(role).value(0); }
};

// A device's faceplate on the overview, laid out by kind: a power unit shows its values
// with bars against their nominal values or limits, a process controller its process
// value large, then setpoint and output, its mode and, where it has one, its program.
struct FaceplateValue
{
    // Where a bar's full scale comes from: fixed bounds, or the value of other entries
    // (their product where there are two: nominal voltage times rated current).
    enum class Scale { None, Range, Nominal, Limit };
    QString entry;
    QString label;   // short, for the faceplate ("Voltage"); the entry's label when the map has none
    Scale scale = Scale::None;
    double barMin = 0;
    double barMax = 100;
    QStringList scaleFrom;
};

// One state a faceplate line can name: the text when "when" (a bool entry or "entry.bit")
// is on; the first one on wins.
struct FaceplateState
{
    QString when;
    QString text;
    bool progress = true;   // a program's segment and time left mean something in this state
};

struct FaceplateSpec
{
    enum class Kind { PowerUnit, ProcessController };
    Kind kind = Kind::PowerUnit;
    QString primary;                 // shown large: the process value
    QString primaryLabel;
    QList<FaceplateValue> values;
    QList<FaceplateState> modes;
    QString modeOtherwise;           // when none of the modes is on (empty: no mode line)
    QString modeNote;                // what the mode cannot tell (a tooltip)
    // The program of a programmer: segment n of m, the time left in it, its state.
    QString programSegment;
    QString programSegments;
    QString programTimeLeft;
    QList<FaceplateState> programStates;
    QString programOtherwise;

    bool hasProgram() const { return !programSegment.isEmpty(); }
};

class RegisterMap
{
public:
    QString family;
    QString name;
    QString shortName;   // for lists: "IPC 300"; the name when the map has none
    QStringList models;
    QString manual;
    QString description;
    QString sourceFile;
    ProtocolInfo protocol;
    QList<IdentifyProbe> identify;
    int scanPriority = 100;
    QMap<int, QString> exceptions;
    std::optional<ErrorValueTexts> errorValues;
    std::optional<SimulationSpec> simulation;
    QStringList overview;   // key values of the overview tile
    FaceplateSpec faceplate;
    QStringList identity;   // entries that identify the device (name, version, serial...)
    // Units set on the device: id to what decides the unit, for the entries that name it.
    QMap<QString, QString> configuredUnits;

    // The family's name in the language shown ("... universal PID controller" is English).
    QString displayName() const;

    const QList<RegisterEntry> &entries() const { return m_entries; }
    void setEntries(QList<RegisterEntry> entries);

    const RegisterEntry *entry(const QString &id) const;
    // The readable entries the faceplate shows, takes its mode and program state from and
    // (with scales) scales its bars by, with the overview's entries, each once.
    QStringList faceplateEntries(bool scales = true) const;
    // The class an entry's kind gives it, unless the map overrides it: see PollClass.
    PollClass derivePollClass(const RegisterEntry &entry) const;
    // Sets every entry's pollClass (after the faceplate and identity are known).
    void assignPollClasses();
    // The entry whose word range contains the address (aliases excluded), or null.
    const RegisterEntry *entryAt(quint16 address) const;
    QString exceptionMeaning(int code) const;

private:
    QList<RegisterEntry> m_entries;   // in address order
    QHash<QString, qsizetype> m_indexById;
};

} // namespace jumo
