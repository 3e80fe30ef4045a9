#pragma once
// cuelab-cli (CONTRACT.md): the subcommands of a setup file, registered in Commands.cpp (Command.h).

#include <QByteArray>
#include <QStringList>

namespace cuelab::cli {

// Exit statuses of CONTRACT.md.
enum ExitStatus : int {
    Success = 0,
    SetupRefused = 1,
    UsageError = 2,
    SimulationUnfinished = 3,  // the event cap was hit, or max_time came before every ball rested
};

// Runs cuelab-cli with `arguments` (program name first), collecting what it prints.
int run(const QStringList& arguments, QByteArray* out, QByteArray* err);

// The same, printing to the process's stdout and stderr.
int run(const QStringList& arguments);

}  // namespace cuelab::cli
