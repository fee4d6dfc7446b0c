using System.CommandLine;
using System.CommandLine.Parsing;
using System.Reflection;

namespace Ballistic.Cli;

/// <summary>
/// The <c>ballistic</c> command line: the root command and its subcommands, runnable in-process with any writers
/// so that tests can drive it exactly as a user would.
/// </summary>
public static class BallisticCli
{
    /// <summary>The one-paragraph description shown at the top of <c>--help</c>.</summary>
    public const string Description =
        "Ballistic: plans and animates sequences of ballistic jumps for legged characters through 3D levels " +
        "(Y up, metres, seconds, gravity (0, -9.81, 0)).";

    /// <summary>The tool's version, from the assembly's informational version.</summary>
    public static string Version =>
        typeof(BallisticCli).Assembly.GetCustomAttribute<AssemblyInformationalVersionAttribute>()?.InformationalVersion
        ?? typeof(BallisticCli).Assembly.GetName().Version?.ToString()
        ?? "unknown";

    /// <summary>Builds the root command with every subcommand; <paramref name="cancellation"/> cancels their jobs.</summary>
    public static RootCommand BuildRootCommand(CancellationToken cancellation = default)
    {
        RootCommand root = new(Description)
        {
            CliCommands.Bake(cancellation),
            CliCommands.Plan(cancellation),
            CliCommands.Demo(cancellation),
            CliCommands.Levels(),
            CliCommands.Characters(),
            PlaytestCommand.Create(cancellation),
            BenchCommand.Create(),
        };
        root.Options.Add(CliCommands.Verbose);

        // The stock --version reports the entry assembly, which is the test host when the tool runs in-process.
        foreach (Option option in root.Options)
        {
            if (option is VersionOption)
            {
                option.Action = new PrintVersionAction();
            }
        }

        return root;
    }

    /// <summary>
    /// One parse error as a phrase for the user: a value of the wrong form says what its option takes, in words
    /// ("--max-nodes takes a whole number, not 'abc'"), never a .NET type name; other errors as the parser says them.
    /// </summary>
    private static string Describe(ParseError e)
    {
        string message = e.Message.TrimEnd('.');
        if (!message.StartsWith("Cannot parse argument", StringComparison.Ordinal))
        {
            return message;
        }

        (string name, Type? type, IReadOnlyList<Token> tokens) = e.SymbolResult switch
        {
            OptionResult o => (o.Option.Name, o.Option.ValueType, o.Tokens),
            ArgumentResult a => (a.Argument.Name, a.Argument.ValueType, a.Tokens),
            _ => ("the value", null, []),
        };
        Type? plain = type is null ? null : Nullable.GetUnderlyingType(type) ?? type;
        string wanted = plain == typeof(int) || plain == typeof(long) ? "a whole number"
            : plain == typeof(double) || plain == typeof(float) ? "a number (a dot for decimals)"
            : "another value";
        return tokens.Count > 0 ? $"{name} takes {wanted}, not '{tokens[^1].Value}'" : $"{name} takes {wanted}";
    }

    private static IEnumerable<string> CommandPath(Command command, RootCommand root)
    {
        var names = new List<string>();
        for (Command? c = command; c is not null && c != root; c = c.Parents.OfType<Command>().FirstOrDefault())
        {
            names.Insert(0, c.Name);
        }

        return names;
    }

    /// <summary>
    /// Parses <paramref name="args"/> and runs the chosen command, writing normal output to <paramref name="output"/>
    /// and errors to <paramref name="error"/>.
    /// </summary>
    /// <param name="args">The command line.</param>
    /// <param name="output">Where normal output goes.</param>
    /// <param name="error">Where errors go: one line each (<c>--verbose</c> adds the stack trace).</param>
    /// <param name="cancellation">Cancels the running job (Ctrl-C, SIGTERM): exit code <see cref="ExitCode.Cancelled"/>.</param>
    /// <returns>The process exit code (<see cref="ExitCode"/>): 0 on success, non-zero on any error.</returns>
    public static int Run(string[] args, TextWriter output, TextWriter error, CancellationToken cancellation = default)
    {
        ArgumentNullException.ThrowIfNull(args);
        ArgumentNullException.ThrowIfNull(output);
        ArgumentNullException.ThrowIfNull(error);

        try
        {
            RootCommand root = BuildRootCommand(cancellation);
            ParseResult parsed = root.Parse(args);
            if (parsed.Errors.Count > 0)
            {
                // One line, not the whole help: what is wrong and where the help is.
                string command = string.Join(' ', CommandPath(parsed.CommandResult.Command, root));
                error.WriteLine($"error: {string.Join("; ", parsed.Errors.Select(Describe))} (see 'ballistic{(command.Length > 0 ? " " + command : "")} --help')");
                return ExitCode.Usage;
            }

            return parsed.Invoke(new InvocationConfiguration { Output = output, Error = error, EnableDefaultExceptionHandler = false, ProcessTerminationTimeout = null });
        }
        catch (Exception e)
        {
            // Commands guard their own work; this is the last boundary (parsing, help), never a stack trace by default.
            error.WriteLine($"error: internal error ({e.GetType().Name}: {e.Message}); please report it (--verbose shows the details)");
            if (args.Contains("--verbose"))
            {
                error.WriteLine(e);
            }

            return ExitCode.Internal;
        }
    }
}
