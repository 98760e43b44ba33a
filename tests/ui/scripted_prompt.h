#pragma once

#include <QString>
#include <QStringList>
#include <deque>

#include "ui/prompt.h"

namespace tt::ui::test {

/// A Prompt for tests: answers from queues filled by the test, records everything asked.
/// An empty queue answers No / Cancel / "" so a forgotten answer never blocks.
class ScriptedPrompt final : public Prompt {
public:
    std::deque<Answer> answers;
    std::deque<QString> fileNames;
    QStringList log;  ///< "ask: <title>", "inform: <title>", "warn: <title>", "open: <title>", "save: <title>"
    QString lastText;

    Answer ask(QWidget*, const QString& title, const QString& question, bool) override {
        log << QStringLiteral("ask: ") + title;
        lastText = question;
        return pop(answers, Answer::No);
    }
    void inform(QWidget*, const QString& title, const QString& text) override {
        log << QStringLiteral("inform: ") + title;
        lastText = text;
    }
    void warn(QWidget*, const QString& title, const QString& text) override {
        log << QStringLiteral("warn: ") + title;
        lastText = text;
    }
    QString openFileName(QWidget*, const QString& title, const QString&) override {
        log << QStringLiteral("open: ") + title;
        return pop(fileNames, QString());
    }
    QString saveFileName(QWidget*, const QString& title, const QString&, const QString&) override {
        log << QStringLiteral("save: ") + title;
        return pop(fileNames, QString());
    }

private:
    template <typename T>
    static T pop(std::deque<T>& queue, T fallback) {
        if (queue.empty()) return fallback;
        T v = queue.front();
        queue.pop_front();
        return v;
    }
};

}  // namespace tt::ui::test
