#pragma once
/// \file value_command.h
/// The undo step "a setting changed": the value before and after, and the function that
/// makes a value current (sets it, updates the controls, recomputes). Any setting of any
/// tab becomes an undo step with one line:
///
///     m_undo->push(new ValueCommand<FitSettings>(apply, m_settings, after, tr("Degree"), id));
///
/// Successive steps with the same merge id (≥ 0) merge into one (QUndoCommand::id(): a slider
/// drag or a spin box held down is one undo); −1 never merges. The tab chooses the id so that
/// only changes of the same setting share it (valueMergeId() for settings named by a string).
/// Like PointsCommand (point_commands.h) for the points.

#include <QHash>
#include <QString>
#include <QUndoCommand>

#include <functional>
#include <utility>

namespace granota::ui {

/// How a ValueCommand behaves beyond the plain "apply before / apply after".
struct ValueCommandOptions {
    /// A merge that brings the value back to where it started removes the step altogether.
    bool dropWhenUnchanged = false;
    /// The tab has made `after` current already (to validate it): the push does not apply it again.
    bool appliedAlready = false;
};

template <class T> class ValueCommand : public QUndoCommand {
public:
    using Apply = std::function<void(const T&)>;

    ValueCommand(Apply apply, T before, T after, const QString& text, int mergeId = -1, ValueCommandOptions options = {},
                 QUndoCommand* parent = nullptr)
        : QUndoCommand(text, parent), m_apply(std::move(apply)), m_before(std::move(before)), m_after(std::move(after)),
          m_mergeId(mergeId), m_options(options), m_skipRedo(options.appliedAlready)
    {
    }

    void undo() override { m_apply(m_before); }
    void redo() override
    {
        if (m_skipRedo) {
            m_skipRedo = false;
            return;
        }
        m_apply(m_after);
    }
    int id() const override { return m_mergeId; }
    bool mergeWith(const QUndoCommand* other) override
    {
        // QUndoStack only asks with the same id(); the cast guards against another command type.
        const auto* next = dynamic_cast<const ValueCommand*>(other);
        if (!next || m_mergeId < 0)
            return false;
        m_after = next->m_after;
        if (m_options.dropWhenUnchanged && m_after == m_before)
            setObsolete(true); // back where it started: no step at all
        return true;
    }

private:
    Apply m_apply;
    T m_before, m_after;
    int m_mergeId;
    ValueCommandOptions m_options;
    bool m_skipRedo;
};

/// A merge id for the setting `name` (e.g. a scene parameter): the same name gives the same id
/// during the whole run, different names different ids, all of them from `base` up.
inline int valueMergeId(int base, const QString& name)
{
    static QHash<QString, int> ids;
    const auto it = ids.constFind(name);
    if (it != ids.constEnd())
        return base + *it;
    const int next = static_cast<int>(ids.size());
    ids.insert(name, next);
    return base + next;
}

} // namespace granota::ui
