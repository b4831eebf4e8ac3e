<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>jumo::CommandLineTool</name>
    <message>
        <location filename="../app/cli/commandlinetool.cpp" line="+17"/>
        <source>Usage: jumoctl COMMAND [options] [arguments]

Commissioning and monitoring of JUMO power and process controllers over Modbus RTU.

Commands on the register maps:
  families                 list the device families and their map files
  map FAMILY --csv|--json  print a family&apos;s register map
  plan FAMILY [ID...]      show the read requests for entries of a family
  decode FAMILY ID WORD... decode raw register words as an entry

&apos;jumoctl COMMAND --help&apos; describes a command.
</source>
        <translation>Aufruf: jumoctl BEFEHL [Optionen] [Argumente]

Inbetriebnahme und Überwachung von JUMO-Leistungs- und Prozessreglern über Modbus RTU.

Befehle für die Registertabellen:
  families                  Gerätefamilien und ihre Map-Dateien auflisten
  map FAMILIE --csv|--json  Registertabelle einer Gerätefamilie ausgeben
  plan FAMILIE [ID...]      Leseanfragen für Einträge einer Gerätefamilie anzeigen
  decode FAMILIE ID WORT... Rohe Registerwörter als Eintrag dekodieren

&apos;jumoctl BEFEHL --help&apos; beschreibt einen Befehl.
</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>warning: refused map file: %1</source>
        <translation>Warnung: Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>jumoctl: unknown command &apos;%1&apos;</source>
        <translation>jumoctl: unbekannter Befehl &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Try &apos;jumoctl --help&apos;.</source>
        <translation>Siehe &apos;jumoctl --help&apos;.</translation>
    </message>
</context>
<context>
    <name>jumo::CommandParser</name>
    <message>
        <location filename="../app/cli/commandparser.cpp" line="+19"/>
        <source>jumoctl %1: %2</source>
        <translation>jumoctl %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+17"/>
        <source>Try &apos;jumoctl %1 --help&apos;.</source>
        <translation>Siehe &apos;jumoctl %1 --help&apos;.</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>jumoctl %1: wrong number of arguments</source>
        <translation>jumoctl %1: falsche Anzahl von Argumenten</translation>
    </message>
</context>
<context>
    <name>jumo::MapCommands</name>
    <message>
        <location filename="../app/cli/mapcommands.cpp" line="+132"/>
        <source>unknown family &apos;%1&apos; (known: %2)</source>
        <translation>unbekannte Gerätefamilie &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Lists the device families and the map files they come from.</source>
        <translation>Listet die Gerätefamilien und die Map-Dateien auf, aus denen sie stammen.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n registers</source>
        <translation>
            <numerusform>%n Register</numerusform>
            <numerusform>%n Register</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>refused map file: %1</source>
        <translation>Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Prints the register map of a device family.</source>
        <translation>Gibt die Registertabelle einer Gerätefamilie aus.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Family id, see &apos;jumoctl families&apos;.</source>
        <translation>Kennung der Gerätefamilie, siehe &apos;jumoctl families&apos;.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV: one row per register and one per bit of a bit field.</source>
        <translation>CSV: eine Zeile je Register und je Bit eines Bitfelds.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JSON: the family&apos;s facts and every register.</source>
        <translation>JSON: die Angaben zur Gerätefamilie und alle Register.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>jumoctl map: give exactly one of --csv and --json</source>
        <translation>jumoctl map: genau eine der Optionen --csv und --json angeben</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Shows the read requests that poll the given entries (all readable entries if none).</source>
        <translation>Zeigt die Leseanfragen, mit denen die angegebenen Einträge abgefragt werden (ohne Angabe alle lesbaren Einträge).</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+28"/>
        <source>Family id.</source>
        <translation>Kennung der Gerätefamilie.</translation>
    </message>
    <message>
        <location line="-27"/>
        <source>Entry ids to read.</source>
        <translation>Kennungen der zu lesenden Einträge.</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>read %1..%2 (%n words): </source>
        <translation>
            <numerusform>lesen %1..%2 (%n Wort): </numerusform>
            <numerusform>lesen %1..%2 (%n Wörter): </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n requests, </source>
        <translation>
            <numerusform>%n Anfrage, </numerusform>
            <numerusform>%n Anfragen, </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n words</source>
        <translation>
            <numerusform>%n Wort</numerusform>
            <numerusform>%n Wörter</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Decodes raw register words (hex, as read from the device) as an entry.</source>
        <translation>Dekodiert rohe Registerwörter (hexadezimal, wie vom Gerät gelesen) als Eintrag.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Entry id.</source>
        <translation>Kennung des Eintrags.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Register words in hex, e.g. 70A3 4145.</source>
        <translation>Registerwörter hexadezimal, z. B. 70A3 4145.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is not a 16-bit hex word</source>
        <translation>&apos;%1&apos; ist kein 16-Bit-Hexwort</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; takes %2 words, %3 given</source>
        <translation>&apos;%1&apos; benötigt %2 Wörter, %3 angegeben</translation>
    </message>
</context>
<context>
    <name>jumo::MapLoader</name>
    <message>
        <location filename="../lib/maploader.cpp" line="+47"/>
        <source>malformed JSON at byte %1: %2</source>
        <translation>fehlerhaftes JSON bei Byte %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the top level must be a JSON object</source>
        <translation>die oberste Ebene muss ein JSON-Objekt sein</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>unknown key &apos;%1&apos;</source>
        <translation>unbekannter Schlüssel &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is missing or not a non-empty string</source>
        <translation>&apos;%1&apos; fehlt oder ist keine nicht leere Zeichenkette</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be a whole number</source>
        <translation>&apos;%1&apos; muss eine ganze Zahl sein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;%1&apos; is missing</source>
        <translation>&apos;%1&apos; fehlt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be a number</source>
        <translation>&apos;%1&apos; muss eine Zahl sein</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; must be 0x followed by 4 hex digits, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos; muss 0x gefolgt von 4 Hexziffern sein, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be a non-empty array of numbers</source>
        <translation>&apos;%1&apos; muss ein nicht leeres Array von Zahlen sein</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; must contain only numbers</source>
        <translation>&apos;%1&apos; darf nur Zahlen enthalten</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;format&apos; must be 1</source>
        <translation>&apos;format&apos; muss 1 sein</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>family id &apos;%1&apos; must be lower case letters, digits and &apos;_&apos;</source>
        <translation>Familienkennung &apos;%1&apos; darf nur aus Kleinbuchstaben, Ziffern und &apos;_&apos; bestehen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;entries&apos; must be a non-empty array</source>
        <translation>&apos;entries&apos; muss ein nicht leeres Array sein</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&apos;protocol&apos; must be an object</source>
        <translation>&apos;protocol&apos; muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&apos;maxReadWords&apos; must be 1..127, not %1</source>
        <translation>&apos;maxReadWords&apos; muss 1..127 sein, nicht %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;maxWriteWords&apos; must be 1..127, not %1</source>
        <translation>&apos;maxWriteWords&apos; muss 1..127 sein, nicht %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; must be ABCD, CDAB, BADC or DCBA, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos; muss ABCD, CDAB, BADC oder DCBA sein, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>unknown data format &apos;%1&apos;</source>
        <translation>unbekanntes Datenformat &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;dataFormats&apos; must list at least one format</source>
        <translation>&apos;dataFormats&apos; muss mindestens ein Format enthalten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>address range %1..%2 is not within 1..255</source>
        <translation>Adressbereich %1..%2 liegt nicht innerhalb von 1..255</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;processingTimeMaxMs&apos; is missing or negative</source>
        <translation>&apos;processingTimeMaxMs&apos; fehlt oder ist negativ</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;identify&apos; must be a non-empty array of probes</source>
        <translation>&apos;identify&apos; muss ein nicht leeres Array von Prüfabfragen sein</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>a probe needs exactly one of textContains, maskNonZero, answers, exception</source>
        <translation>eine Prüfabfrage benötigt genau eines von textContains, maskNonZero, answers, exception</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;words&apos; must be 1..125</source>
        <translation>&apos;words&apos; muss 1..125 sein</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;exceptions&apos; must be an object mapping codes to meanings</source>
        <translation>&apos;exceptions&apos; muss ein Objekt sein, das Codes ihren Bedeutungen zuordnet</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not an exception code with a text</source>
        <translation>&apos;%1&apos; ist kein Exception-Code mit Text</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;errorValues&apos; must be an object or null</source>
        <translation>&apos;errorValues&apos; muss ein Objekt oder null sein</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>entry #%1</source>
        <translation>Eintrag #%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>an entry must be an object</source>
        <translation>ein Eintrag muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>entry #%1 (%2)</source>
        <translation>Eintrag #%1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+162"/>
        <location line="+21"/>
        <source>entry &apos;%1&apos; (%2)</source>
        <translation>Eintrag &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="-173"/>
        <source>id must be lower case letters, digits and &apos;_&apos;</source>
        <translation>die Kennung darf nur aus Kleinbuchstaben, Ziffern und &apos;_&apos; bestehen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown type &apos;%1&apos; (expected float, int16, uint16, int32, uint32, bool, enum, bitfield or text)</source>
        <translation>unbekannter Typ &apos;%1&apos; (erwartet: float, int16, uint16, int32, uint32, bool, enum, bitfield oder text)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown access &apos;%1&apos; (expected R, W or RW)</source>
        <translation>unbekannter Zugriff &apos;%1&apos; (erwartet: R, W oder RW)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown storage &apos;%1&apos; (expected RAM or EEPROM)</source>
        <translation>unbekannter Speicherort &apos;%1&apos; (erwartet: RAM oder EEPROM)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a read-only entry cannot have a storage</source>
        <translation>ein nur lesbarer Eintrag kann keinen Speicherort haben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a text needs &apos;bytes&apos; (at least 2, including the NUL)</source>
        <translation>ein Text benötigt &apos;bytes&apos; (mindestens 2, einschließlich des NUL)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;bytes&apos; is only for texts</source>
        <translation>&apos;bytes&apos; ist nur für Texte zulässig</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;words&apos; is only for reserved blocks and must be at least 1</source>
        <translation>&apos;words&apos; ist nur für reservierte Blöcke zulässig und muss mindestens 1 sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;min&apos; is greater than &apos;max&apos;</source>
        <translation>&apos;min&apos; ist größer als &apos;max&apos;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>unknown control &apos;%1&apos;</source>
        <translation>unbekanntes Bedienelement &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a control needs a writable entry</source>
        <translation>ein Bedienelement benötigt einen schreibbaren Eintrag</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&apos;values&apos; is only for enums</source>
        <translation>&apos;values&apos; ist nur für Enums zulässig</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>an enum needs &apos;values&apos;</source>
        <translation>ein Enum benötigt &apos;values&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>enum value &apos;%1&apos; must be a number 0..65535 with a text</source>
        <translation>Enum-Wert &apos;%1&apos; muss eine Zahl 0..65535 mit einem Text sein</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;bits&apos; is only for bit fields</source>
        <translation>&apos;bits&apos; ist nur für Bitfelder zulässig</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a bit field needs &apos;bits&apos;</source>
        <translation>ein Bitfeld benötigt &apos;bits&apos;</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1, bit %2</source>
        <translation>%1, Bit %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bit number must be 0..15</source>
        <translation>Bitnummer muss 0..15 sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bit field of width %1 does not fit in 16 bits</source>
        <translation>Bitfeld der Breite %1 passt nicht in 16 Bit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a bit needs an id of lower case letters, digits and &apos;_&apos;</source>
        <translation>ein Bit benötigt eine Kennung aus Kleinbuchstaben, Ziffern und &apos;_&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>duplicate bit id &apos;%1&apos;</source>
        <translation>doppelte Bitkennung &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a bit needs a label</source>
        <translation>ein Bit benötigt eine Bezeichnung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown kind &apos;%1&apos; (expected alarm, warning, status or command)</source>
        <translation>unbekannte Art &apos;%1&apos; (erwartet: alarm, warning, status oder command)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit defined twice</source>
        <translation>Bit doppelt definiert</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>duplicate id (also at %1)</source>
        <translation>doppelte Kennung (auch bei %1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+2"/>
        <source>entry &apos;%1&apos;</source>
        <translation>Eintrag &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>alias of unknown entry &apos;%1&apos;</source>
        <translation>Alias eines unbekannten Eintrags &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>runs past address 0xFFFF</source>
        <translation>reicht über Adresse 0xFFFF hinaus</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>words %1..%2 overlap entry &apos;%3&apos; (%4..%5)</source>
        <translation>Wörter %1..%2 überschneiden sich mit Eintrag &apos;%3&apos; (%4..%5)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: cannot open: %2</source>
        <translation>%1: kann nicht geöffnet werden: %2</translation>
    </message>
</context>
<context>
    <name>jumo::ReadPlanner</name>
    <message>
        <location filename="../lib/readplanner.cpp" line="+32"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>&apos;%1&apos; (%2) is write-only</source>
        <translation>&apos;%1&apos; (%2) ist nur schreibbar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; (%2) spans words that are not all readable</source>
        <translation>&apos;%1&apos; (%2) umfasst Wörter, die nicht alle lesbar sind</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; (%2) has %3 words, more than the %4 words one read may take</source>
        <translation>&apos;%1&apos; (%2) hat %3 Wörter, mehr als die %4 Wörter, die eine Leseanfrage umfassen darf</translation>
    </message>
</context>
<context>
    <name>jumo::RegisterMap</name>
    <message>
        <location filename="../lib/registermap.cpp" line="+142"/>
        <source>exception %1 (not documented for this family)</source>
        <translation>Exception-Code %1 (für diese Gerätefamilie nicht dokumentiert)</translation>
    </message>
</context>
<context>
    <name>jumo::RegisterMapBrowser</name>
    <message>
        <location filename="../ui/registermapbrowser.cpp" line="+18"/>
        <source>JUMO register maps</source>
        <translation>JUMO-Registertabellen</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>No register maps could be loaded.</source>
        <translation>Es konnten keine Registertabellen geladen werden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 - %2 registers - models: %3 - manual: %4</source>
        <translation>%1 - %2 Register - Modelle: %3 - Handbuch: %4</translation>
    </message>
</context>
<context>
    <name>jumo::RegisterMapModel</name>
    <message>
        <location filename="../lib/registermapmodel.cpp" line="+36"/>
        <source>Correction of the manual: %1</source>
        <translation>Korrektur des Handbuchs: %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Label</source>
        <translation>Bezeichnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Storage</source>
        <translation>Speicherort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Section</source>
        <translation>Abschnitt</translation>
    </message>
</context>
<context>
    <name>jumo::ValueCodec</name>
    <message>
        <location filename="../lib/valuecodec.cpp" line="+88"/>
        <source>Underrange</source>
        <translation>Unterlauf</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Overrange</source>
        <translation>Überlauf</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid</source>
        <translation>Ungültig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Decode error</source>
        <translation>Dekodierfehler</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>expected %1 words, got %2</source>
        <translation>%1 Wörter erwartet, %2 erhalten</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>not a boolean: %1</source>
        <translation>kein boolescher Wert: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown value %1</source>
        <translation>unbekannter Wert %1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>&apos;%1&apos; is read-only</source>
        <translation>&apos;%1&apos; ist nur lesbar</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no value given for &apos;%1&apos;</source>
        <translation>kein Wert für &apos;%1&apos; angegeben</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is outside the range of &apos;%2&apos; (%3 to %4)</source>
        <translation>%1 liegt außerhalb des Bereichs von &apos;%2&apos; (%3 bis %4)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not a whole number</source>
        <translation>&apos;%1&apos; ist keine ganze Zahl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 does not fit the type of &apos;%2&apos; (%3 to %4)</source>
        <translation>%1 passt nicht zum Typ von &apos;%2&apos; (%3 bis %4)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; ist keine Zahl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is too large for a float</source>
        <translation>%1 ist zu groß für einen float</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>&apos;%1&apos; is not a boolean (0/1, on/off, true/false)</source>
        <translation>&apos;%1&apos; ist kein boolescher Wert (0/1, on/off, true/false)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;%1&apos; is not a value of &apos;%2&apos; (%3)</source>
        <translation>&apos;%1&apos; ist kein Wert von &apos;%2&apos; (%3)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 does not fit in 16 bits</source>
        <translation>%1 passt nicht in 16 Bit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not a bit of &apos;%2&apos;</source>
        <translation>&apos;%1&apos; ist kein Bit von &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the text for &apos;%1&apos; must be at most %2 Latin-1 characters</source>
        <translation>der Text für &apos;%1&apos; darf höchstens %2 Latin-1-Zeichen lang sein</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/jumo-hmi.cpp" line="+19"/>
        <source>JUMO commissioning and monitoring HMI.</source>
        <translation>JUMO-HMI für Inbetriebnahme und Überwachung.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start on the built-in simulated bus (one device of each family).</source>
        <translation>Auf dem eingebauten simulierten Bus starten (ein Gerät jeder Familie).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Control-room mode: nothing is ever written to the devices.</source>
        <translation>Leitwarten-Modus: Es wird nie etwas auf die Geräte geschrieben.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Map files refused</source>
        <translation>Map-Dateien abgelehnt</translation>
    </message>
</context>
</TS>
