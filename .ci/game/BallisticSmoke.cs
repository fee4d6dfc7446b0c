// A Godot game's own code using Ballistic, minus Godot: what a game script does in _Ready and _PhysicsProcess.
// Built by .ci/game-check against the packages the README tells users to pack, on net8.0 (a Godot 4.7 game's target).
using System;
using System.IO;
using System.Numerics;
using Ballistic.Planner.Animation;
using Ballistic.Planner.Levels;
using Ballistic.Planner.Planning;
using Ballistic.Runtime;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Baking;
using Ballistic.Runtime.Events;
using Ballistic.Runtime.Kinds;

namespace MyGame;

public static class BallisticSmoke
{
    public static int Run(string ballistic)
    {
        Level level = GltfLevelLoader.Load(Path.Combine(ballistic, "Scenes", "levels", "gap-course.glb"));
        var (model, character) = CharacterAsset.FromFiles(
            Path.Combine(ballistic, "Scenes", "characters", "skeleton.glb"),
            Path.Combine(ballistic, "Scenes", "characters", "skeleton.limbs.json")).Load();
        BakeOutcome bake = BakeJob.Run(level, character, BakeJob.Settings(seed: 1, maxNodes: 300, timeLimitSeconds: 60));
        Console.WriteLine(bake);
        if (!bake.Succeeded)
        {
            return 1;
        }

        var scene = PlanningScene.Create(level, character);
        using var world = new JumpWorld(level);
        KindHandle skeleton = world.AddKind(new CharacterKind(scene, bake.Roadmap!, new JumpAnimator(scene, model))).Kind;
        AgentHandle npc = world.AddAgent(skeleton, new Vector3(-6f, 0f, 0f)).Agent;
        Console.WriteLine($"target set: {world.SetTarget(npc, new Vector3(11.5f, 1f, 0f)).Ok}");
        int jumps = 0;
        for (int tick = 0; tick < 60 * 120; tick++)
        {
            world.Step();
            foreach (JumpEvent e in world.Events)
            {
                jumps += e.Kind == JumpEventKind.JumpStarted ? 1 : 0;
                if (e.Kind == JumpEventKind.PathFailed)
                {
                    Console.WriteLine($"path failed: {e.Reason}");
                    return 1;
                }

                if (e.Kind == JumpEventKind.TargetReached)
                {
                    Console.WriteLine($"target reached after {jumps} jumps at tick {tick}, root at {world.GetRootPose(npc).Position}");
                    return 0;
                }
            }
        }

        Console.WriteLine("the target was not reached in 120 s");
        return 1;
    }
}
