namespace Ballistic.Planner.Tests.Godot;

/// <summary>The table of Godot classes and properties the scene checks rely on.</summary>
public sealed class GodotClassesTests
{
    [Test]
    public void EveryClassDescendsFromObjectThroughKnownClasses()
    {
        foreach (GodotClass cls in GodotClasses.All.Values)
        {
            IReadOnlyList<GodotClass> chain = GodotClasses.Chain(cls.Name);
            Assert.That(chain[^1].Name, Is.EqualTo("Object"), $"{cls.Name}'s chain ends at {chain[^1].Name}");
            Assert.That(chain.Select(c => c.Name).Distinct().Count(), Is.EqualTo(chain.Count), $"{cls.Name}'s chain has a cycle");
        }
    }

    [Test]
    public void NoClassRepeatsAPropertyOfItsAncestorsOrItself()
    {
        foreach (GodotClass cls in GodotClasses.All.Values)
        {
            Assert.That(cls.Properties, Is.Unique, cls.Name);
            Assert.That(cls.Properties, Has.All.Matches<string>(p => p.Length > 0 && p == p.ToLowerInvariant() && !p.Contains(' ', StringComparison.Ordinal)), cls.Name);
            string[] inherited = GodotClasses.Chain(cls.Name).Skip(1).SelectMany(c => c.Properties).ToArray();
            Assert.That(cls.Properties.Intersect(inherited), Is.Empty, $"{cls.Name} repeats inherited properties");
        }
    }

    [Test]
    public void TheClassesTheAddonUsesAreKnown()
    {
        string[] used =
        [
            "Node3D", "MeshInstance3D", "Camera3D", "DirectionalLight3D", "WorldEnvironment", "StaticBody3D", "CollisionShape3D",
            "Label3D", "NavigationRegion3D", "NavigationAgent3D", "Skeleton3D", "AnimationPlayer", "CharacterBody3D", "Resource",
        ];
        Assert.That(used.Where(c => !GodotClasses.IsKnown(c)), Is.Empty);
    }

    [TestCase("MeshInstance3D", "transform", true)]
    [TestCase("MeshInstance3D", "mesh", true)]
    [TestCase("MeshInstance3D", "cast_shadow", true)]
    [TestCase("MeshInstance3D", "surface_material_override/0", true)]
    [TestCase("MeshInstance3D", "surface_material_override/", false)]
    [TestCase("MeshInstance3D", "metadata/_edit_lock_", true)]
    [TestCase("MeshInstance3D", "shape", false)]
    [TestCase("Node3D", "Transform", false)]
    [TestCase("Node", "visible", false)]
    [TestCase("CharacterBody3D", "collision_layer", true)]
    [TestCase("CharacterBody3D", "axis_lock_linear_y", true)]
    [TestCase("Skeleton3D", "bones/3/rest", true)]
    [TestCase("AnimationPlayer", "libraries", true)]
    [TestCase("AnimationPlayer", "root_node", true)]
    [TestCase("Resource", "resource_name", true)]
    [TestCase("Resource", "script", true)]
    [TestCase("Resource", "visible", false)]
    [TestCase("Unknown3D", "transform", false)]
    public void APropertyBelongsToAClassThroughItsChain(string cls, string key, bool expected) =>
        Assert.That(GodotClasses.HasProperty(cls, key), Is.EqualTo(expected));

    [TestCase("StaticBody3D", "Node3D", true)]
    [TestCase("StaticBody3D", "CollisionObject3D", true)]
    [TestCase("Node3D", "StaticBody3D", false)]
    [TestCase("Resource", "Node", false)]
    [TestCase("AnimationPlayer", "Node", true)]
    public void InheritanceFollowsTheTable(string derived, string ancestor, bool expected) =>
        Assert.That(GodotClasses.Inherits(derived, ancestor), Is.EqualTo(expected));
}
