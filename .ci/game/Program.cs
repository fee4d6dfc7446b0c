// Entry point of the stand-in game (a Godot game has none: the engine loads its assembly). Argument: the Ballistic clone.
namespace MyGame;

public static class Program
{
    public static int Main(string[] args) => BallisticSmoke.Run(args[0]);
}
