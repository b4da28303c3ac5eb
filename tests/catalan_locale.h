#pragma once
// The locale of a Catalan desktop, for the tests that check that numbers in files, streams
// and the command line do not follow it. ca_ES.UTF-8 writes 0.5 as "0,5": a test that runs
// without it proves nothing, so its absence is a failure, not a skip (.ci/deps.sh makes it).
#include <QStringList>

#include <clocale>
#include <cstdlib>
#include <cstring>
#include <string>

inline constexpr const char* kCatalanLocale = "ca_ES.UTF-8";
inline constexpr const char* kMissingCatalan = "the ca_ES.UTF-8 locale is missing: generate it (locale-gen), see .ci/deps.sh";

/// The environment of a process started on a Catalan desktop.
inline QStringList catalanEnvironment()
{
    return {QStringLiteral("LANG=ca_ES.UTF-8"), QStringLiteral("LC_ALL=ca_ES.UTF-8"), QStringLiteral("LANGUAGE=ca")};
}

/// Switches this process's C locale to Catalan; true when it took and has a decimal comma.
inline bool enterCatalanLocale()
{
    if (!std::setlocale(LC_ALL, kCatalanLocale))
        return false;
    return std::strcmp(std::localeconv()->decimal_point, ",") == 0;
}

/// Switches LC_NUMERIC to Catalan (decimal comma) for one scope, and back.
class CatalanNumbers {
public:
    CatalanNumbers() : m_saved(std::setlocale(LC_NUMERIC, nullptr)) { m_active = std::setlocale(LC_NUMERIC, kCatalanLocale); }
    ~CatalanNumbers() { std::setlocale(LC_NUMERIC, m_saved.c_str()); }
    bool active() const { return m_active; }

private:
    std::string m_saved;
    bool m_active = false;
};
