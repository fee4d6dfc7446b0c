#nullable enable
using System.Collections.Generic;
using Ballistic.Addon;
using Godot;

namespace Ballistic.Scenes;

/// <summary>
/// The playtest scene's controls: a left click on the level sends every NPC there; R sends each NPC to a random
/// stance of its roadmap; F1 toggles the roadmap debug view, F2 the paths and cones; each NPC's <see cref="Label3D"/>
/// shows its agent's state. Demo glue only: the agents and the runtime do the work.
/// </summary>
public partial class PlaytestController : Node3D
{
    private readonly RandomNumberGenerator _random = new() { Seed = 7 };
    private readonly List<(JumpAgent3D Agent, Label3D? Label)> _npcs = [];

    /// <summary>Send each NPC to a random stance when the roadmaps are ready and whenever one arrives.</summary>
    [Export]
    public bool Wander { get; set; } = true;

    /// <summary>Finds the NPCs (every <see cref="JumpAgent3D"/> in the scene) and their labels.</summary>
    public override void _Ready()
    {
        foreach (Node node in FindChildren("*", "", recursive: true, owned: false))
        {
            if (node is JumpAgent3D agent)
            {
                Label3D? label = agent.GetParent()?.FindChildren("*", nameof(Label3D), recursive: false, owned: false).OfType<Label3D>().FirstOrDefault();
                _npcs.Add((agent, label));
                agent.TargetReached += () => { if (Wander) { SendToRandomStance(agent); } };
                agent.PathFailed += reason => { GD.Print($"{agent.GetParent()?.Name}: {reason}"); if (Wander) { SendToRandomStance(agent); } };
            }
        }
    }

    /// <summary>Updates the labels; starts wandering once the roadmaps are loaded.</summary>
    public override void _Process(double delta)
    {
        foreach ((JumpAgent3D agent, Label3D? label) in _npcs)
        {
            if (label is not null)
            {
                label.Text = $"{agent.GetParent()?.Name}\n{agent.GetStateText()}";
            }

            if (Wander && agent.IsNavigationFinished() && !agent.IsTargetReached() && agent.GetRoadmap()?.LoadedRoadmap is not null && agent.Logic is { HasTarget: false })
            {
                SendToRandomStance(agent);
            }
        }
    }

    /// <summary>Clicks and keys.</summary>
    public override void _UnhandledInput(InputEvent @event)
    {
        if (@event is InputEventMouseButton { ButtonIndex: MouseButton.Left, Pressed: true } click && GetViewport().GetCamera3D() is { } camera)
        {
            Vector3 from = camera.ProjectRayOrigin(click.Position);
            Vector3 to = from + (camera.ProjectRayNormal(click.Position) * 500f);
            foreach ((JumpAgent3D agent, _) in _npcs)
            {
                if (agent.GetRoadmap()?.IntersectLevel(from, to) is Vector3 hit)
                {
                    agent.TargetPosition = hit;
                }
            }
        }
        else if (@event is InputEventKey { Pressed: true, Echo: false } key && JumpNavigationServer.Singleton is { } server)
        {
            switch (key.Keycode)
            {
                case Key.F1:
                    server.DrawRoadmaps = !server.DrawRoadmaps;
                    break;
                case Key.F2:
                    server.DrawPaths = !server.DrawPaths;
                    break;
                case Key.R:
                    _npcs.ForEach(npc => SendToRandomStance(npc.Agent));
                    break;
            }
        }
    }

    private void SendToRandomStance(JumpAgent3D agent)
    {
        if (agent.GetRoadmap()?.LoadedRoadmap is { Nodes.Count: > 0 } roadmap)
        {
            agent.TargetPosition = roadmap.ContactCentres[(int)_random.RandiRange(0, roadmap.Nodes.Count - 1)].ToGodot();
        }
    }
}
