// Catalan and English (docs/classroom.md): no untranslated string in either language, and every
// translation keeps the placeholders (%1, %2, %n) of its source, so no message ever shows
// a raw "%1" or loses a number.
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QTest>
#include <QXmlStreamReader>

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
        const auto messages =
            readTs(QStringLiteral(GRANOTA_SOURCE_DIR "/translations/granota_%1.ts").arg(language));
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
};

QTEST_APPLESS_MAIN(TestTranslations)
#include "test_translations.moc"
