#include "tests/fuzz/ui_properties.h"

#include "core/io/point_list.h"
#include "ui/bernstein/bernstein_tab.h"
#include "ui/bsplines/bspline_tab.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/shell/document.h"
#include "ui/fit/fit_tab.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/common/tab_page.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>

#include <cmath>
#include <exception>
#include <functional>
#include <memory>

namespace granota::fuzz {

using ui::TabPage;

namespace {

std::string shown(const QByteArray& bytes)
{
    constexpr int kMax = 300;
    return "«" + bytes.left(kMax).toStdString() + (bytes.size() > kMax ? "…" : "") + "»";
}

/// Where two byte strings first differ, with some context on each side.
std::string difference(const QByteArray& a, const QByteArray& b)
{
    qsizetype i = 0;
    while (i < a.size() && i < b.size() && a[i] == b[i])
        ++i;
    const qsizetype from = std::max<qsizetype>(0, i - 80);
    return "at byte " + std::to_string(i) + ": " + shown(a.mid(from, 160)) + " against " + shown(b.mid(from, 160));
}

std::string guarded(const std::function<std::string()>& check)
{
    std::string finding;
    try {
        finding = check();
    } catch (const std::exception& e) {
        finding = std::string("exception escaped: ") + e.what();
    } catch (...) {
        finding = "a non-standard exception escaped";
    }
    // What an event loop would have done by now (queued replots, deferred deletes), so
    // that nothing piles up from one input to the next.
    QCoreApplication::sendPostedEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    return finding;
}

std::string firstNonFinite(const QJsonValue& v, const std::string& path)
{
    if (v.isDouble())
        return std::isfinite(v.toDouble()) ? std::string() : path;
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        for (qsizetype i = 0; i < a.size(); ++i)
            if (auto bad = firstNonFinite(a.at(i), path + "[" + std::to_string(i) + "]"); !bad.empty())
                return bad;
    } else if (v.isObject()) {
        const QJsonObject o = v.toObject();
        for (auto it = o.begin(); it != o.end(); ++it)
            if (auto bad = firstNonFinite(it.value(), path + "." + it.key().toStdString()); !bad.empty())
                return bad;
    }
    return {};
}

/// The six tabs, built as MainWindow builds them (the Bernstein tab follows the
/// De Casteljau tab's points), owned by a widget that is never shown.
class Tabs {
public:
    Tabs() : m_owner(std::make_unique<QWidget>())
    {
        auto* deCasteljau = new ui::DeCasteljauTab(m_owner.get());
        pages = {deCasteljau,
                 new ui::BernsteinTab(deCasteljau->curveModel(), m_owner.get()),
                 new ui::FitTab(m_owner.get()),
                 new ui::CatmullRomTab(m_owner.get()),
                 new ui::FrogTab(m_owner.get()),
                 new ui::BSplineTab(m_owner.get())};
    }
    QVector<TabPage*> pages;

private:
    std::unique_ptr<QWidget> m_owner;
};

const QString kBlankTab = QStringLiteral("decasteljau");

/// After opening a document the main window forgets the tabs' undo history; so do we (it
/// would otherwise grow with every input).
void clearUndo(const QVector<TabPage*>& pages)
{
    for (TabPage* page : pages)
        page->undoStack()->clear();
}

std::string documentProperty(std::string_view input)
{
    static Tabs* const tabs = new Tabs; // kept for the whole run (reachable: not a leak)
    static const QByteArray blank = serializeDocument(tabs->pages, kBlankTab);
    static bool loaded = false; // the tabs hold the previous input's document

    // Every input starts from the blank document, as File ▸ New does. (A refused input
    // leaves the tabs blank, which is checked below: only an accepted one needs undoing.)
    QString error, current;
    if (loaded) {
        loaded = false;
        if (!loadDocument(blank, tabs->pages, &error, &current))
            return "the blank document is refused: " + error.toStdString();
        clearUndo(tabs->pages);
        if (const QByteArray now = serializeDocument(tabs->pages, kBlankTab); now != blank)
            return "loading the blank document does not give it back, " + difference(blank, now);
    }

    const QByteArray bytes(input.data(), static_cast<qsizetype>(input.size()));
    error.clear();
    current.clear();
    if (!loadDocument(bytes, tabs->pages, &error, &current)) {
        if (error.isEmpty())
            return "the document was refused without a message";
        if (const QByteArray now = serializeDocument(tabs->pages, kBlankTab); now != blank)
            return "the refused document (“" + error.toStdString() + "”) changed the tabs, " + difference(blank, now);
        return {};
    }
    loaded = true;
    clearUndo(tabs->pages);
    for (const TabPage* tab : tabs->pages)
        if (auto bad = firstNonFinite(tab->saveState(), tab->key().toStdString()); !bad.empty())
            return "a non-finite number was loaded into " + bad;
    const QByteArray saved = serializeDocument(tabs->pages, current);

    Tabs fresh;
    QString freshError, freshCurrent;
    if (!loadDocument(saved, fresh.pages, &freshError, &freshCurrent))
        return "fresh tabs refuse the document saved after loading it (“" + freshError.toStdString() + "”): " + shown(saved);
    if (freshCurrent != current)
        return "the current tab “" + current.toStdString() + "” reads back as “" + freshCurrent.toStdString() + "”";
    if (const QByteArray again = serializeDocument(fresh.pages, freshCurrent); again != saved)
        return "load → save → load into fresh tabs → save changed the document, " + difference(saved, again);
    return {};
}

struct FitHarness {
    QWidget owner;
    ui::FitTab* tab = new ui::FitTab(&owner);
    ui::FitTab* other = new ui::FitTab(&owner);
    QJsonObject blank = tab->saveState();
    QTemporaryDir dir;
    QString path = dir.path() + QStringLiteral("/points.csv");
};

std::string fitImportProperty(std::string_view input)
{
    static FitHarness* const h = new FitHarness; // kept for the whole run (reachable: not a leak)
    if (!h->dir.isValid())
        return "no temporary directory";
    QString error;
    if (!h->tab->loadState(h->blank, &error))
        return "the blank Fitting tab's state is refused: " + error.toStdString();
    h->tab->undoStack()->clear();
    h->other->undoStack()->clear();
    {
        QFile file(h->path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
            file.write(input.data(), static_cast<qint64>(input.size())) != static_cast<qint64>(input.size()))
            return "cannot write " + h->path.toStdString();
    }
    const QJsonObject before = h->tab->saveState();
    error.clear();
    if (!h->tab->importFile(h->path, &error)) {
        if (error.isEmpty())
            return "the file was refused without a message";
        if (h->tab->saveState() != before)
            return "the refused file (“" + error.toStdString() + "”) changed the Fitting tab";
        return {};
    }
    const QJsonObject state = h->tab->saveState();
    if (auto bad = firstNonFinite(state, "fit"); !bad.empty())
        return "a non-finite number was imported: " + bad;
    const QJsonArray points = state.value(QStringLiteral("points")).toArray();
    if (points.size() < 2)
        return "the import gave the tab " + std::to_string(points.size()) + " point(s); a fit needs 2";
    const auto parsed = parsePointFile(input);
    if (!parsed)
        return "the tab imported a file that parsePointFile refuses: " + parsed.error().message;
    const std::vector<Point> expected = toDouble(*parsed);
    if (expected.size() != static_cast<std::size_t>(points.size()))
        return "the file holds " + std::to_string(expected.size()) + " points, the tab " + std::to_string(points.size());
    for (qsizetype i = 0; i < points.size(); ++i) {
        const QJsonArray xy = points.at(i).toArray();
        const Point p{xy.at(0).toDouble(), xy.at(1).toDouble()};
        if (!(p == expected[static_cast<std::size_t>(i)]))
            return "point " + std::to_string(i) + " of the file became another point in the tab";
    }
    // What was imported can be saved and opened again.
    if (!h->other->loadState(state, &error))
        return "another Fitting tab refuses the imported state: " + error.toStdString();
    if (h->other->saveState() != state)
        return "the imported state does not load unchanged into another Fitting tab";
    return {};
}

} // namespace

void initUi()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("GranotaFuzz"));
    QCoreApplication::setApplicationName(QStringLiteral("GranotaFuzz"));
    ui::setLanguage(QStringLiteral("en"), false);
}

std::string checkDocument(std::string_view input)
{
    return guarded([&] { return documentProperty(input); });
}
std::string checkFitImport(std::string_view input)
{
    return guarded([&] { return fitImportProperty(input); });
}

std::string checkUi(std::string_view target, std::string_view input)
{
    if (target == "document")
        return checkDocument(input);
    if (target == "fit_import")
        return checkFitImport(input);
    return "no fuzz target is called '" + std::string(target) + "'";
}

} // namespace granota::fuzz
