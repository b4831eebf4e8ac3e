// Runs a jumoctl command in-process, as the executable would, and collects its exit
// code and output; commands that work on the event loop are waited for.
#pragma once

#include "commandlinetool.h"

#include <QSignalSpy>
#include <QTextStream>

namespace jumo::test {

struct Run
{
    int code = -1;
    QString out;
    QString err;
};

inline Run run(const QStringList &args)
{
    Run r;
    QTextStream out(&r.out);
    QTextStream err(&r.err);
    CommandLineTool tool(out, err);
    QSignalSpy finished(&tool, &CommandLineTool::finished);
    if (const std::optional<int> code = tool.run(args))
        r.code = *code;
    else if (finished.wait(60000))
        r.code = finished.first().first().toInt();
    out.flush();
    err.flush();
    return r;
}

} // namespace jumo::test
