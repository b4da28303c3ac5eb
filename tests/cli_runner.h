#pragma once
// Runs the real granota-cli for the CLI tests and collects what it printed.
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <QTest>
#include <QtGlobal>

struct CliRun {
    int exitCode = -1; ///< -2 when the process crashed, -1 when it did not finish
    QByteArray out, err;
    QJsonObject json() const
    {
        QJsonParseError e;
        const auto doc = QJsonDocument::fromJson(out, &e);
        if (e.error != QJsonParseError::NoError || !doc.isObject())
            qWarning("not a JSON object: %s", out.constData());
        return doc.object();
    }
};

/// Runs granota-cli with `env` added to the environment (e.g. a desktop's locale).
inline CliRun runCliWith(const QStringList& env, const QStringList& args, int timeoutMs = 300000);

inline CliRun runCli(const QStringList& args, int timeoutMs = 300000) { return runCliWith({}, args, timeoutMs); }

/// Runs granota-cli with its standard output written to `stdoutFile` (e.g. "/dev/full"
/// to see what it does when the output cannot be written); CliRun::out stays empty.
inline CliRun runCliToFile(const QString& stdoutFile, const QStringList& args, int timeoutMs = 300000);

namespace cli_runner_detail {

/// `wrapper`, when given, is a command that runs granota-cli: its program and its first
/// arguments, then granota-cli's path and `args` follow (a shell setting ulimit, say).
inline CliRun run(const QStringList& env, const QString& stdoutFile, const QStringList& args, int timeoutMs,
                  const QStringList& wrapper = {})
{
    QProcess p;
    if (!stdoutFile.isEmpty())
        p.setStandardOutputFile(stdoutFile);
    if (!env.isEmpty()) {
        QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
        for (const QString& kv : env)
            e.insert(kv.section(QLatin1Char('='), 0, 0), kv.section(QLatin1Char('='), 1));
        p.setProcessEnvironment(e);
    }
    if (wrapper.isEmpty())
        p.start(QStringLiteral(GRANOTA_CLI_PATH), args);
    else
        p.start(wrapper.front(), wrapper.mid(1) + QStringList{QStringLiteral(GRANOTA_CLI_PATH)} + args);
    CliRun r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        qWarning("granota-cli did not finish: %s", qPrintable(args.join(' ')));
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

} // namespace cli_runner_detail

inline CliRun runCliWith(const QStringList& env, const QStringList& args, int timeoutMs)
{
    return cli_runner_detail::run(env, QString(), args, timeoutMs);
}

inline CliRun runCliToFile(const QString& stdoutFile, const QStringList& args, int timeoutMs)
{
    return cli_runner_detail::run({}, stdoutFile, args, timeoutMs);
}

/// Runs granota-cli with its address space limited to `kib` KiB (`ulimit -v`).
inline CliRun runCliInAddressSpace(const QString& kib, const QStringList& args, int timeoutMs)
{
    return cli_runner_detail::run({}, QString(), args, timeoutMs,
                                  {QStringLiteral("/bin/sh"), QStringLiteral("-c"),
                                   QStringLiteral("ulimit -v %1; exec \"$0\" \"$@\"").arg(kib)});
}

/// What granota-cli does with bad input (docs/cli.md): exit 2 and "error: …" on standard
/// error; with OutputOnRefusal::Empty, nothing on standard output either.
enum class OutputOnRefusal { Any, Empty };

/// For a data-driven test whose column "args" holds argument lists granota-cli must refuse:
/// runs the current row and checks that it was refused.
inline void verifyRowIsRefused(OutputOnRefusal output = OutputOnRefusal::Any)
{
    QFETCH(QStringList, args);
    const CliRun run = runCli(args);
    QCOMPARE(run.exitCode, 2);
    QVERIFY2(run.err.startsWith("error: "), run.err.constData());
    if (output == OutputOnRefusal::Empty)
        QVERIFY(run.out.isEmpty());
}
