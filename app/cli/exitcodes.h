// The exit codes of jumoctl, as the README documents them for scripts.
#pragma once

namespace jumo::exitcode {

constexpr int Ok = 0;
constexpr int Failed = 1;         // timeouts, exceptions, refused writes, files not written
constexpr int Usage = 2;          // wrong arguments or input files
constexpr int Uncertain = 3;      // write: an outcome is unknown or unverified, check the device
constexpr int WrongDevice = 4;    // the device at the address is not of the named family
constexpr int HungUp = 129;       // SIGHUP (128 + 1): the terminal was closed
constexpr int Interrupted = 130;  // SIGINT (128 + 2)
constexpr int OutputClosed = 141; // SIGPIPE (128 + 13): the output's reader is gone (| head)
constexpr int Terminated = 143;   // SIGTERM (128 + 15)

} // namespace jumo::exitcode
