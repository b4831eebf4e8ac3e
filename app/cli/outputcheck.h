// Whether what a command printed reached its reader: stdout can be a file on a full disk,
// or a pipe whose reader has gone (jumoctl restore ... | head).
#pragma once

class QTextStream;

namespace jumo::OutputCheck {

// A write to the stream's file failed (after it was flushed).
bool failed(QTextStream &stream);
// The stream's reader is gone: the far end of its pipe or socket was closed. Nothing
// printed from now on is read.
bool closed(const QTextStream &stream);

} // namespace jumo::OutputCheck
