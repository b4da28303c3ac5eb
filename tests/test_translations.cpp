// Catalan and English (docs/classroom.md): no untranslated string in either language, and every
// translation keeps the placeholders (%1, %2, %n) of its source, so no message ever shows
// a raw "%1" or loses a number.
#include <QDebug>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTest>
#include "tests/test_main.h"
#include <QXmlStreamReader>

#include <algorithm>

namespace {

struct Message {
    QString context, source;
    QStringList translations; ///< one, or one per plural form
    QString type;             ///< "unfinished", "vanished", "obsolete" or empty
};

QList<Message> readTs(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    QXmlStreamReader xml(&file);
    QList<Message> out;
    QString context;
    Message current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            if (xml.name() == QLatin1String("name"))
                context = xml.readElementText();
            else if (xml.name() == QLatin1String("message"))
                current = Message{context, {}, {}, {}};
            else if (xml.name() == QLatin1String("source"))
                current.source = xml.readElementText();
            else if (xml.name() == QLatin1String("translation")) {
                current.type = xml.attributes().value(QLatin1String("type")).toString();
                // Plain text, or <numerusform> children.
                QString text;
                while (!(xml.isEndElement() && xml.name() == QLatin1String("translation")) && !xml.atEnd()) {
                    xml.readNext();
                    if (xml.isCharacters())
                        text += xml.text();
                    if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                        current.translations << xml.readElementText();
                }
                if (current.translations.isEmpty())
                    current.translations << text;
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            out << current;
        }
    }
    if (xml.hasError())
        qFatal("%s: %s", qPrintable(path), qPrintable(xml.errorString()));
    return out;
}

QSet<QString> placeholders(const QString& text)
{
    static const QRegularExpression re(QStringLiteral("%(\\d+|n)"));
    QSet<QString> found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured(0));
    return found;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void everyMessageIsTranslated_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("ca") << QStringLiteral("ca");
        QTest::newRow("en") << QStringLiteral("en");
    }
    void everyMessageIsTranslated()
    {
        QFETCH(QString, language);
        const auto messages = readTs(QStringLiteral(GRANOTA_SOURCE_DIR "/translations/granota_%1.ts").arg(language));
        QVERIFY(messages.size() > 500); // every tab's texts are there
        QStringList problems;
        int differing = 0;
        for (const Message& m : messages) {
            if (m.type == QLatin1String("vanished") || m.type == QLatin1String("obsolete"))
                continue;
            if (m.type == QLatin1String("unfinished"))
                problems << QStringLiteral("unfinished [%1] %2").arg(m.context, m.source);
            for (const QString& t : m.translations) {
                if (t.trimmed().isEmpty())
                    problems << QStringLiteral("empty [%1] %2").arg(m.context, m.source);
                else if (placeholders(t) != placeholders(m.source))
                    problems << QStringLiteral("placeholders [%1] %2 → %3").arg(m.context, m.source, t);
                differing += t != m.source;
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        if (language == QLatin1String("ca"))
            QVERIFY(differing > messages.size() * 3 / 4); // Catalan really is Catalan
    }

    // Issue 34, item 11: labels, tooltips and the status bar write indices as the panels do
    // (tᵢ, wⱼ, Bᵢⁿ, 10¹⁶), never as typed markup ("t_i", "w_j", "B_i^n", "10^16"): a plain-text
    // widget would show the underscore and caret as they are.
    void noTypedMarkupInAnyMessage_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("ca") << QStringLiteral("ca");
        QTest::newRow("en") << QStringLiteral("en");
    }
    void noTypedMarkupInAnyMessage()
    {
        QFETCH(QString, language);
        // A single letter with an index after "_" ("t_i", "q_{i+1}", "P_(i−1)"), or a number or
        // letter raised with "^" ("t^i", "10^16", "^(n−i)"); names such as "area_factor" are not.
        static const QRegularExpression markup(
            QStringLiteral("(?<![A-Za-z_])[A-Za-zσ]_(?:[ijkn0-9]\\b|[{(])|[A-Za-z0-9)]\\^(?:[0-9ni(]|\\{)"));
        const auto messages = readTs(QStringLiteral(GRANOTA_SOURCE_DIR "/translations/granota_%1.ts").arg(language));
        QStringList found;
        for (const auto& m : messages)
            for (const QString& text : QStringList{m.source} + m.translations)
                if (text.contains(markup))
                    found << m.context + QStringLiteral(": ") + text.left(80);
        QVERIFY2(found.isEmpty(), qPrintable(found.join(QLatin1Char('\n'))));
    }

    // Item 18 of the classroom pass: one word per concept (translations/GLOSSARY.md). Every
    // Catalan message whose source names a concept of the glossary uses the glossary's word
    // for it and none of the words it replaced; the English interface shows no Catalan word.
    void glossaryIsFollowed()
    {
        QFile file(QStringLiteral(GRANOTA_SOURCE_DIR "/translations/GLOSSARY.md"));
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        struct Row {
            QString english;
            QStringList catalan, notCatalan, notEnglish;
        };
        QList<Row> rows;
        bool inTable = false;
        const auto split = [](const QString& cell) {
            QStringList out;
            for (const QString& part : cell.split(QLatin1Char('/'), Qt::SkipEmptyParts))
                if (!part.trimmed().isEmpty())
                    out << part.trimmed();
            return out;
        };
        for (const QString& line : QString::fromUtf8(file.readAll()).split(QLatin1Char('\n'))) {
            if (!line.startsWith(QLatin1Char('|'))) {
                inTable = false;
                continue;
            }
            const QStringList cells = line.split(QLatin1Char('|'));
            if (cells.size() < 6 || cells[1].trimmed() == QLatin1String("English"))
                continue;
            if (cells[1].trimmed().startsWith(QLatin1String("---"))) {
                inTable = true;
                continue;
            }
            if (inTable)
                rows << Row{cells[1].trimmed(), split(cells[2]), split(cells[3]), split(cells[4])};
        }
        QVERIFY2(rows.size() >= 10, "the glossary's table was not read");

        QStringList failures;
        const auto catalan = readTs(QStringLiteral(GRANOTA_SOURCE_DIR "/translations/granota_ca.ts"));
        for (const Row& row : rows) {
            // Not inside a file name ("docs/thesis-errata.md").
            const QRegularExpression term(QStringLiteral("\\b") + QRegularExpression::escape(row.english) +
                                              QStringLiteral("(?![-.])"),
                                          QRegularExpression::CaseInsensitiveOption);
            int uses = 0;
            for (const Message& m : catalan) {
                if (m.type == QLatin1String("obsolete") || m.type == QLatin1String("vanished"))
                    continue;
                for (QString t : m.translations) {
                    t.remove(QLatin1Char('&')); // accelerators: "Mode de &presentació"
                    for (const QString& banned : row.notCatalan)
                        if (t.contains(banned))
                            failures << QStringLiteral("%1: “%2” in “%3”").arg(m.context, banned, t.left(80));
                    if (!QString(m.source).remove(QLatin1Char('&')).contains(term))
                        continue;
                    ++uses;
                    const bool named = std::any_of(row.catalan.begin(), row.catalan.end(),
                                                   [&t](const QString& word) { return t.contains(word, Qt::CaseInsensitive); });
                    if (!named)
                        failures << QStringLiteral("%1: “%2” is not “%3” in “%4”")
                                        .arg(m.context, row.english, row.catalan.join(QStringLiteral(" / ")), t.left(80));
                }
            }
            if (uses == 0)
                failures << QStringLiteral("the glossary's “%1” names nothing the interface says").arg(row.english);
        }
        const auto english = readTs(QStringLiteral(GRANOTA_SOURCE_DIR "/translations/granota_en.ts"));
        for (const Row& row : rows)
            for (const QString& banned : row.notEnglish)
                for (const Message& m : english)
                    for (const QString& t : m.translations)
                        if (t.contains(banned))
                            failures << QStringLiteral("English %1: “%2” in “%3”").arg(m.context, banned, t.left(80));
        for (const QString& failure : failures) // QVERIFY2 cuts long messages: each on its own line
            qWarning().noquote() << failure;
        QVERIFY2(failures.isEmpty(), qPrintable(QStringLiteral("%1 messages break the glossary").arg(failures.size())));
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestTranslations)
#include "test_translations.moc"
