// granota-cli and the files it reads and writes (issue 32, docs/cli.md "Files"): an output
// keeps the old file until the new one is whole (on a real full disk), no output may name
// an input or another output, a pipe given as an input is refused at once, text from a file
// is escaped before it reaches the terminal, and a closed pipe on stdout is exit 2 with a
// message, not a death by SIGPIPE.
#include "cli_runner.h"
#include "full_disk.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

/// A run that cannot end by itself (a hang) is stopped after this: a guard, not a timing.
constexpr int kHangGuardMs = 120000;

QByteArray contentOf(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("(missing)");
}

bool put(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size() && f.flush();
}

/// Every name in `folder`, hidden files included: nothing left behind by a refusal.
QStringList namesIn(const QString& folder)
{
    return QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

/// A recording of three steps of the frog, written by granota-cli itself.
QByteArray frogRecording(const QTemporaryDir& dir)
{
    const QString path = dir.filePath(QStringLiteral("made.json"));
    const CliRun run = runCli({"simulate", "--scene", "frog", "--steps", "3", "--record", path});
    if (run.exitCode != 0)
        return QByteArray();
    QByteArray bytes = contentOf(path);
    QFile::remove(path);
    return bytes;
}

/// Runs granota-cli with its standard output the write end of a pipe whose read end is
/// already closed, as `granota-cli demo | true` once `true` has exited; SIGPIPE at its
/// default (killing) action, whatever the test process does with it.
CliRun runIntoClosedPipe(const QStringList& args)
{
    int ends[2];
    CliRun r;
    if (::pipe2(ends, O_CLOEXEC) != 0)
        return r;
    ::close(ends[0]);
    const int writeEnd = ends[1];
    QProcess p;
    p.setChildProcessModifier([writeEnd] {
        ::signal(SIGPIPE, SIG_DFL);
        ::dup2(writeEnd, STDOUT_FILENO);
    });
    p.start(QStringLiteral(GRANOTA_CLI_PATH), args);
    const bool finished = p.waitForFinished(kHangGuardMs);
    ::close(writeEnd);
    if (!finished) {
        p.kill();
        p.waitForFinished();
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.err = p.readAllStandardError();
    return r;
}

} // namespace

class TestCliFiles : public QObject {
    Q_OBJECT
private slots:
    // A: every file output of simulate onto a real full disk (a tmpfs filled to the
    // byte; report's files: test_cli_report): exit 2, "cannot write …: No space left on device", the old file byte for byte,
    // and no hidden file left beside it.
    void outputsOnAFullDiskKeepTheOldFile_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("file");
        QTest::newRow("trace") << QStringList{"simulate", "--scene", "frog", "--steps", "50", "--trace", "FILE"}
                               << QStringLiteral("out.csv");
        QTest::newRow("series") << QStringList{"simulate", "--scene", "frog", "--steps", "50", "--series", "FILE"}
                                << QStringLiteral("out.csv");
        QTest::newRow("record") << QStringList{"simulate", "--scene", "frog", "--steps", "50", "--record", "FILE"}
                                << QStringLiteral("out.json");
    }
    void outputsOnAFullDiskKeepTheOldFile()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, file);
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        const QByteArray old = "the old file, which must survive\n";
        QVERIFY(disk.put(file, old));
        QVERIFY(disk.fill());
        args.replaceInStrings(QStringLiteral("FILE"), disk.filePath(file));
        const CliRun run = runCli(args, kHangGuardMs);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith("error: cannot write ") && run.err.endsWith(": No space left on device\n"),
                 run.err.constData());
        QCOMPARE(disk.read(file), old);
        QCOMPARE(namesIn(disk.filePath(QString())), QStringList({QStringLiteral("filler"), file}));
    }

    // A: a successful run replaces an old output with the new one whole.
    void aSuccessfulRunReplacesTheOutputs()
    {
        QTemporaryDir dir;
        const QString trace = dir.filePath(QStringLiteral("t.csv")), series = dir.filePath(QStringLiteral("s.csv"));
        QVERIFY(put(trace, "old trace\n") && put(series, "old series\n"));
        const CliRun run = runCli({"simulate", "--scene", "frog", "--steps", "5", "--trace", trace, "--series", series});
        QCOMPARE(run.exitCode, 0);
        // A header and one row a step, the state before the first too: 1 + 6 lines each.
        QCOMPARE(contentOf(trace).count('\n'), 7);
        QCOMPARE(contentOf(series).count('\n'), 7);
        QCOMPARE(namesIn(dir.path()), QStringList({QStringLiteral("s.csv"), QStringLiteral("t.csv")}));
    }

    // B: an output naming an input or another output, by any spelling (the same path, a
    // "./" in it, a link), is refused with exit 2 before anything is read or written: every
    // input and every old output byte for byte, no file created.
    void aliasedFilesAreRefused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QStringList replay{"simulate", "--replay", "DIR/r.json"};
        QTest::newRow("trace = replay") << replay + QStringList{"--trace", "DIR/r.json"}
                                        << "error: --trace and --replay name the same file\n";
        QTest::newRow("trace = ./replay") << replay + QStringList{"--trace", "DIR/./r.json"}
                                          << "error: --trace and --replay name the same file\n";
        QTest::newRow("series = link to replay")
            << replay + QStringList{"--series", "DIR/link.json"} << "error: --series and --replay name the same file\n";
        QTest::newRow("record = replay") << replay + QStringList{"--record", "DIR/sub/../r.json"}
                                         << "error: --record and --replay name the same file\n";
        const QStringList frog{"simulate", "--scene", "frog", "--steps", "3"};
        QTest::newRow("trace = ./series, new") << frog + QStringList{"--trace", "DIR/c.csv", "--series", "DIR/./c.csv"}
                                               << "error: --series and --trace name the same file\n";
        QTest::newRow("trace = series, old") << frog + QStringList{"--trace", "DIR/old.csv", "--series", "DIR/old.csv"}
                                             << "error: --series and --trace name the same file\n";
        QTest::newRow("trace = link to record") << frog + QStringList{"--trace", "DIR/old.csv", "--record", "DIR/oldlink.csv"}
                                                << "error: --trace and --record name the same file\n";
    }
    void aliasedFilesAreRefused()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QByteArray recording = frogRecording(dir);
        QVERIFY(!recording.isEmpty());
        QVERIFY(put(dir.filePath(QStringLiteral("r.json")), recording));
        QVERIFY(put(dir.filePath(QStringLiteral("old.csv")), "an old output\n"));
        QVERIFY(QFile::link(dir.filePath(QStringLiteral("r.json")), dir.filePath(QStringLiteral("link.json"))));
        QVERIFY(QFile::link(dir.filePath(QStringLiteral("old.csv")), dir.filePath(QStringLiteral("oldlink.csv"))));
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("sub")));
        const QStringList before = namesIn(dir.path());
        args.replaceInStrings(QStringLiteral("DIR"), dir.path());
        const CliRun run = runCli(args, kHangGuardMs);
        QCOMPARE(run.exitCode, 2);
        QCOMPARE(run.err, message.toUtf8());
        QVERIFY(run.out.isEmpty());
        QCOMPARE(contentOf(dir.filePath(QStringLiteral("r.json"))), recording);
        QCOMPARE(contentOf(dir.filePath(QStringLiteral("old.csv"))), QByteArray("an old output\n"));
        QCOMPARE(namesIn(dir.path()), before);
    }

    // B: two outputs that are not the same file are written both; /dev/null twice is fine
    // (a device is never "the same file": nothing is lost).
    void distinctOutputsAndDevicesRun()
    {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("sub")));
        const CliRun run = runCli({"simulate", "--scene", "frog", "--steps", "2", "--trace",
                                   dir.filePath(QStringLiteral("c.csv")), "--series", dir.filePath(QStringLiteral("sub/c.csv"))});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(contentOf(dir.filePath(QStringLiteral("c.csv"))).startsWith("step,"));
        QVERIFY(!contentOf(dir.filePath(QStringLiteral("sub/c.csv"))).startsWith("step,x"));
        const CliRun devices = runCli(
            {"simulate", "--scene", "frog", "--steps", "2", "--trace", "/dev/null", "--series", "/dev/null"});
        QCOMPARE(devices.exitCode, 0);
    }

    // B: an argument refused after the outputs were named leaves every old output as it was
    // (before, --trace was truncated first and the refusal came after).
    void refusedArgumentsLeaveOldOutputs_data()
    {
        QTest::addColumn<QStringList>("args");
        const QStringList frog{"simulate", "--scene", "frog", "--steps", "3", "--trace", "DIR/t.csv"};
        QTest::newRow("series-body without series") << frog + QStringList{"--series-body", "1"};
        QTest::newRow("series-body out of range") << frog + QStringList{"--series", "DIR/s.csv", "--series-body", "99"};
        QTest::newRow("series-body not a number") << frog + QStringList{"--series", "DIR/s.csv", "--series-body", "x"};
        QTest::newRow("too many rows") << QStringList{"simulate", "--scene",   "polygon",  "--steps",  "5000000",
                                                      "--trace",  "DIR/t.csv", "--series", "DIR/s.csv"};
        QTest::newRow("record in no folder") << frog + QStringList{"--record", "DIR/none/r.json"};
    }
    void refusedArgumentsLeaveOldOutputs()
    {
        QFETCH(QStringList, args);
        QTemporaryDir dir;
        QVERIFY(put(dir.filePath(QStringLiteral("t.csv")), "old trace\n"));
        QVERIFY(put(dir.filePath(QStringLiteral("s.csv")), "old series\n"));
        args.replaceInStrings(QStringLiteral("DIR"), dir.path());
        const CliRun run = runCli(args, kHangGuardMs);
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith("error: "), run.err.constData());
        QCOMPARE(contentOf(dir.filePath(QStringLiteral("t.csv"))), QByteArray("old trace\n"));
        QCOMPARE(contentOf(dir.filePath(QStringLiteral("s.csv"))), QByteArray("old series\n"));
        QCOMPARE(namesIn(dir.path()), QStringList({QStringLiteral("s.csv"), QStringLiteral("t.csv")}));
    }

    // C: every command that reads a file, given a named pipe nobody writes to: refused at
    // once (exit 2, "… is a pipe, not a file"), never a wait in open().
    void aPipeAsInputIsRefused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("bezier") << QStringList{"bezier", "--points-file", "FIFO", "--t", "1/2"};
        QTest::newRow("analyze") << QStringList{"analyze", "--points-file", "FIFO"};
        QTest::newRow("project") << QStringList{"project", "--points-file", "FIFO", "--at", "0,0"};
        QTest::newRow("fit") << QStringList{"fit", "--points-file", "FIFO", "--degree", "1"};
        QTest::newRow("catmull-rom") << QStringList{"catmull-rom", "--points-file", "FIFO"};
        QTest::newRow("simulate --replay") << QStringList{"simulate", "--replay", "FIFO"};
        QTest::newRow("simulate --replay, with a trace") << QStringList{"simulate", "--replay", "FIFO", "--trace", "OUT"};
    }
    void aPipeAsInputIsRefused()
    {
        QFETCH(QStringList, args);
        QTemporaryDir dir;
        const QString fifo = dir.filePath(QStringLiteral("fifo"));
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        args.replaceInStrings(QStringLiteral("FIFO"), fifo);
        args.replaceInStrings(QStringLiteral("OUT"), dir.filePath(QStringLiteral("t.csv")));
        const CliRun run = runCli(args, kHangGuardMs);
        QCOMPARE(run.exitCode, 2);
        QCOMPARE(run.err, "error: '" + fifo.toUtf8() + "' is a pipe, not a file\n");
        QCOMPARE(namesIn(dir.path()), QStringList({QStringLiteral("fifo")}));
    }

    // D: a forged recording whose scene title and component hold an ESC sequence that
    // clears the screen and a newline followed by a fake "finite: yes": the text answer shows
    // them escaped, one line each, and the only "finite:" line is the real one.
    void aForgedRecordingIsShownEscaped()
    {
        QTemporaryDir dir;
        const QByteArray recording = frogRecording(dir);
        QVERIFY(!recording.isEmpty());
        QJsonObject doc = QJsonDocument::fromJson(recording).object();
        QJsonObject scene = doc.value(QStringLiteral("scene")).toObject();
        const QString forged = QStringLiteral("\033[2J\nfinite: yes");
        scene.insert(QStringLiteral("title"), forged);
        scene.insert(QStringLiteral("section"), forged);
        doc.insert(QStringLiteral("scene"), scene);
        const QString path = dir.filePath(QStringLiteral("forged.json"));
        QVERIFY(put(path, QJsonDocument(doc).toJson()));
        const CliRun run = runCli({"simulate", "--replay", path}, kHangGuardMs);
        QCOMPARE(run.exitCode, 0);
        for (char c : run.out)
            QVERIFY2(c == '\n' || static_cast<unsigned char>(c) >= 0x20, run.out.toPercentEncoding(" :'/()=,\n").constData());
        QVERIFY2(run.out.contains("\\x1b[2J\\nfinite: yes"), run.out.constData());
        int finiteLines = 0;
        for (const QByteArray& line : run.out.split('\n'))
            finiteLines += line.startsWith("finite:") ? 1 : 0;
        QCOMPARE(finiteLines, 1);
        // --json escapes it as JSON does: the title is not part of the answer, the scene's
        // name is, and it reads back as written.
        const CliRun json = runCli({"simulate", "--replay", path, "--json"}, kHangGuardMs);
        QCOMPARE(json.exitCode, 0);
        QCOMPARE(json.json().value(QStringLiteral("scene")).toString(), QStringLiteral("frog"));
    }

    // F: a recording cut short, and numbers no computation can hold, in plain words.
    void plainMessages()
    {
        QTemporaryDir dir;
        const QByteArray recording = frogRecording(dir);
        QVERIFY(recording.size() > 100);
        const QString cut = dir.filePath(QStringLiteral("cut.json"));
        QVERIFY(put(cut, recording.left(73)));
        // The line is one more than the newlines in the 73 bytes kept.
        const QByteArray line = QByteArray::number(1 + recording.left(73).count('\n'));
        const CliRun replay = runCli({"simulate", "--replay", cut}, kHangGuardMs);
        QCOMPARE(replay.exitCode, 2);
        QCOMPARE(replay.err, "error: '" + cut.toUtf8() + "' is not JSON: the file is cut off at byte 73 (line " + line + ")\n");
        const CliRun t = runCli({"bezier", "--points", "0,0;1,1", "--t", "1e1000000"});
        QCOMPARE(t.exitCode, 2);
        QCOMPARE(t.err, QByteArray("error: --t '1e1000000' is too large (the largest double is about 1.8e308)\n"));
        const CliRun point = runCli({"fit", "--points", "0,0;1e1000000,1", "--degree", "1"});
        QCOMPARE(point.exitCode, 2);
        QVERIFY2(point.err.endsWith("'1e1000000' is too large (the largest double is about 1.8e308)\n"), point.err.constData());
    }

    // E: the answer written into a pipe whose reader has gone: exit 2 and the message of
    // docs/cli.md, not a silent death by SIGPIPE (status 141 in a shell). A big answer (a
    // long Catmull-Rom sample table) and a small one alike.
    void aClosedPipeIsAnError_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("demo") << QStringList{"demo"};
        QTest::newRow("demo json") << QStringList{"demo", "--json"};
        QTest::newRow("help") << QStringList{"--help"};
        QTest::newRow("catmull-rom table") << QStringList{"catmull-rom", "--points", "3,5;2,2;6,0;8,3;7,5;1,1;0,4;9,9",
                                                          "--samples",   "10000",    "--json"};
    }
    void aClosedPipeIsAnError()
    {
        QFETCH(QStringList, args);
        const CliRun run = runIntoClosedPipe(args);
        QCOMPARE(run.exitCode, 2);
        QCOMPARE(run.err, QByteArray("error: cannot write the output: Broken pipe\n"));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCliFiles)
#include "test_cli_files.moc"
